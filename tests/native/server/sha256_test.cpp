// server/store/sha256.h: FIPS 180-4 test vectors, padding edges, constant-time comparison.
#include "store/sha256.h"

#include <gtest/gtest.h>

#include <string>

namespace sw::store {
namespace {

TEST(Sha256, FipsVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PaddingBoundaries) {
  // 55 bytes fit the length in one block, 56 need a second: both must differ and be stable.
  std::string a55(55, 'x'), a56(56, 'x'), a64(64, 'x');
  EXPECT_NE(sha256_hex(a55), sha256_hex(a56));
  EXPECT_EQ(sha256_hex(a56), sha256_hex(std::string(56, 'x')));
  EXPECT_EQ(sha256_hex(a64).size(), 64u);
}

TEST(Sha256, ConstantTimeEqual) {
  EXPECT_TRUE(constant_time_equal("abcdef", "abcdef"));
  EXPECT_FALSE(constant_time_equal("abcdef", "abcdeg"));
  EXPECT_FALSE(constant_time_equal("abc", "abcd"));
}

}  // namespace
}  // namespace sw::store
