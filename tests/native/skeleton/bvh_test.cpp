// BVH import/export (skeleton/bvh.h): structure, conventions, exact round trip, malformed
// catalogue.
#include "skeleton/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "skeleton/local_to_model.h"

namespace sw::skeleton {
namespace {

// A small arm in centimetres: a root with 6 channels in an unusual order, joints with the three
// common rotation orders, End Sites, CRLF line endings on one line and a trailing blank line.
const char* const kArm =
    "HIERARCHY\n"
    "ROOT Hips\n"
    "{\n"
    "\tOFFSET 0.00 90.00 0.00\n"
    "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "\tJOINT RightArm\n"
    "\t{\n"
    "\t\tOFFSET -15.0 40.0 0.0\r\n"
    "\t\tCHANNELS 3 Xrotation Yrotation Zrotation\n"
    "\t\tJOINT RightForeArm\n"
    "\t\t{\n"
    "\t\t\tOFFSET -27.0 0.0 0.0\n"
    "\t\t\tCHANNELS 3 Yrotation Zrotation Xrotation\n"
    "\t\t\tEnd Site\n"
    "\t\t\t{\n"
    "\t\t\t\tOFFSET -25.0 0.0 0.0\n"
    "\t\t\t}\n"
    "\t\t}\n"
    "\t}\n"
    "\tJOINT Head\n"
    "\t{\n"
    "\t\tOFFSET 0 60 0\n"
    "\t\tCHANNELS 3 Zrotation Yrotation Xrotation\n"
    "\t\tEnd Site\n"
    "\t\t{\n"
    "\t\t\tOFFSET 0 20 0\n"
    "\t\t}\n"
    "\t}\n"
    "}\n"
    "MOTION\n"
    "Frames: 2\n"
    "Frame Time: 0.033333\n"
    "1.0 90.0 -2.5 10 20 30 0 0 90 45 0 0 5 -5 15\n"
    "1.5 91.0 -2.0 -10 -20 -30 90 0 0 0 45 0 -5 5 -15\n"
    "\n";

Bvh read_ok(const std::string& text) {
  const BvhReadResult r = read_bvh(text);
  EXPECT_TRUE(r.ok) << r.error.format();
  return r.bvh;
}

TEST(BvhRead, HierarchyChannelsAndMotion) {
  const Bvh bvh = read_ok(kArm);
  ASSERT_EQ(bvh.joints.size(), 4u);
  EXPECT_EQ(bvh.joints[0].name, "Hips");
  EXPECT_EQ(bvh.joints[2].name, "RightForeArm");
  EXPECT_EQ(bvh.joints[2].parent, 1);
  EXPECT_EQ(bvh.joints[3].parent, 0);
  EXPECT_EQ(bvh.joints[1].offset, glm::dvec3(-15, 40, 0));
  EXPECT_TRUE(bvh.joints[2].has_end_site);
  EXPECT_EQ(bvh.joints[2].end_site_offset, glm::dvec3(-25, 0, 0));
  EXPECT_FALSE(bvh.joints[1].has_end_site);
  EXPECT_EQ(bvh.joints[0].rotation_order(), math::EulerOrder::ZXY);
  EXPECT_EQ(bvh.joints[1].rotation_order(), math::EulerOrder::XYZ);
  EXPECT_EQ(bvh.joints[2].rotation_order(), math::EulerOrder::YZX);
  EXPECT_EQ(bvh.joints[3].rotation_order(), math::EulerOrder::ZYX);
  EXPECT_TRUE(bvh.joints[0].has_position());
  EXPECT_FALSE(bvh.joints[1].has_position());
  EXPECT_EQ(bvh.channel_count(), 15);
  EXPECT_EQ(bvh.channel_offset(2), 9);
  EXPECT_EQ(bvh.frame_count, 2);
  EXPECT_DOUBLE_EQ(bvh.frame_time_s, 0.033333);
  EXPECT_DOUBLE_EQ(bvh.frame(1)[6], 90.0);
}

TEST(BvhRead, FrameToLocalAppliesChannelOrderInDegrees) {
  const Bvh bvh = read_ok(kArm);
  std::vector<math::Transform> local(bvh.joints.size());
  ASSERT_TRUE(frame_to_local(bvh, 0, 0.01, local));
  // Root: position channels replace the OFFSET, scaled to metres.
  EXPECT_NEAR(local[0].translation.x, 0.01f, 1e-7f);
  EXPECT_NEAR(local[0].translation.y, 0.90f, 1e-6f);
  // Root rotation: Zrotation 10, Xrotation 20, Yrotation 30 listed -> R = Rz(10) Rx(20) Ry(30).
  const glm::dquat expected =
      math::quat_from_euler(glm::radians(glm::dvec3(20, 30, 10)), math::EulerOrder::ZXY);
  EXPECT_NEAR(std::fabs(glm::dot(glm::dquat(local[0].rotation), expected)), 1.0, 1e-6);
  // RightArm: Xrotation 0, Yrotation 0, Zrotation 90: the forearm's offset -X turns to -Y.
  EXPECT_NEAR(local[1].translation.y, 0.40f, 1e-6f);
  const glm::vec3 forearm = local[1].rotation * glm::vec3(-1, 0, 0);
  EXPECT_NEAR(forearm.y, -1.0f, 1e-6f);
  EXPECT_FALSE(frame_to_local(bvh, 2, 0.01, local));
  std::vector<math::Transform> too_small(2);
  EXPECT_FALSE(frame_to_local(bvh, 0, 0.01, too_small));
}

TEST(BvhRead, SkeletonAndFkFromBvh) {
  const Bvh bvh = read_ok(kArm);
  const Skeleton s = to_skeleton(bvh, 0.01, true);
  ASSERT_EQ(s.validate(), "");
  ASSERT_EQ(s.joint_count(), 6);
  EXPECT_EQ(s.joints[4].name, "RightForeArm_end");
  EXPECT_EQ(s.joints[4].parent, 2);
  std::vector<math::Transform> local(6);
  for (int i = 0; i < 6; ++i)
    local[static_cast<std::size_t>(i)] = s.joints[static_cast<std::size_t>(i)].rest;
  ASSERT_TRUE(frame_to_local(bvh, 1, 0.01, local));  // fills the first 4; end sites keep rest
  std::vector<glm::mat4> model(6);
  LocalToModelJob job;
  job.skeleton = &s;
  job.input = local;
  job.output = model;
  ASSERT_TRUE(job.run());
  // Frame 1: hips at (1.5, 91, -2) cm rotated; check against an explicit product for the wrist.
  const glm::mat4 wrist =
      local[0].to_matrix() * local[1].to_matrix() * local[2].to_matrix() * local[4].to_matrix();
  EXPECT_LT(glm::length(glm::vec3(model[4][3]) - glm::vec3(wrist[3])), 1e-6f);
}

TEST(BvhRoundTrip, WriteReadWriteIsByteIdentical) {
  const Bvh bvh = read_ok(kArm);
  const std::string once = write_bvh(bvh);
  const Bvh again = read_ok(once);
  const std::string twice = write_bvh(again);
  EXPECT_EQ(once, twice);
  ASSERT_EQ(again.joints.size(), bvh.joints.size());
  for (std::size_t i = 0; i < bvh.joints.size(); ++i) {
    EXPECT_EQ(again.joints[i].name, bvh.joints[i].name);
    EXPECT_EQ(again.joints[i].parent, bvh.joints[i].parent);
    EXPECT_EQ(again.joints[i].channels, bvh.joints[i].channels);
    EXPECT_EQ(again.joints[i].has_end_site, bvh.joints[i].has_end_site);
    EXPECT_EQ(again.joints[i].end_site_offset, bvh.joints[i].end_site_offset);
  }
  EXPECT_EQ(again.values, bvh.values);  // these values are exact at 6 decimals
}

TEST(BvhRoundTrip, RandomValuesSurviveToPrintedPrecision) {
  Bvh bvh = read_ok(kArm);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(-180.0, 180.0);
  bvh.frame_count = 50;
  bvh.values.resize(50u * 15u);
  for (double& v : bvh.values) v = value(rng);
  for (int decimals : {3, 6, 9}) {
    BvhWriteOptions options;
    options.decimals = decimals;
    const std::string text = write_bvh(bvh, options);
    const Bvh back = read_ok(text);
    ASSERT_EQ(back.values.size(), bvh.values.size());
    const double half_unit = 0.5 * std::pow(10.0, -decimals) * (1 + 1e-9);
    for (std::size_t i = 0; i < bvh.values.size(); ++i) {
      ASSERT_LE(std::fabs(back.values[i] - bvh.values[i]), half_unit + 1e-12) << i;
    }
    EXPECT_EQ(write_bvh(back, options), text);
  }
}

TEST(BvhRoundTrip, LocalTransformsThroughChannelsAndBack) {
  Bvh bvh = read_ok(kArm);
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<math::Transform> local(bvh.joints.size());
  for (auto& t : local) {
    t.translation = {u(rng), u(rng), u(rng)};
    t.rotation = glm::normalize(glm::quat(u(rng), u(rng), u(rng), u(rng)));
  }
  for (std::size_t i = 1; i < local.size(); ++i)
    local[i].translation = glm::vec3(bvh.joints[i].offset * 0.01);
  ASSERT_TRUE(local_to_frame(local, 0.01, bvh, 1));
  const Bvh back = read_ok(write_bvh(bvh));
  std::vector<math::Transform> decoded(bvh.joints.size());
  ASSERT_TRUE(frame_to_local(back, 1, 0.01, decoded));
  for (std::size_t i = 0; i < local.size(); ++i) {
    EXPECT_NEAR(std::fabs(glm::dot(decoded[i].rotation, local[i].rotation)), 1.0f, 1e-6f) << i;
    EXPECT_LT(glm::length(decoded[i].translation - local[i].translation), 1e-6f) << i;
  }
}

TEST(BvhRoundTrip, ExportedAngleTracksAreContinuous) {
  // A joint turning from 170° to 190° about Z is written as 170, 190 — not 170, -170, which a BVH
  // player would interpolate the long way round.
  Bvh bvh = read_ok(kArm);
  bvh.frame_count = 2;
  bvh.values.assign(2u * 15u, 0.0);
  std::vector<math::Transform> local(bvh.joints.size());
  const int arm = bvh.find("RightArm");  // channels Xrotation Yrotation Zrotation
  for (int f = 0; f < 2; ++f) {
    local[static_cast<std::size_t>(arm)].rotation =
        glm::angleAxis(glm::radians(f == 0 ? 170.0f : 190.0f), glm::vec3(0, 0, 1));
    ASSERT_TRUE(local_to_frame(local, 0.01, bvh, f));
  }
  const int z = bvh.channel_offset(arm) + 2;
  EXPECT_NEAR(bvh.frame(0)[z], 170.0, 1e-4);
  EXPECT_NEAR(bvh.frame(1)[z], 190.0, 1e-4);
}

TEST(BvhWrite, NonDepthFirstArrayIsWrittenInFileOrder) {
  // Joints stored breadth first: the writer emits depth first and permutes the frame values to
  // match.
  Bvh bvh;
  const auto joint = [](const char* name, int parent) {
    BvhJoint j;
    j.name = name;
    j.parent = parent;
    j.channels = {BvhChannel::Zrotation, BvhChannel::Xrotation, BvhChannel::Yrotation};
    return j;
  };
  bvh.joints = {joint("root", -1), joint("a", 0), joint("b", 0), joint("a1", 1)};
  bvh.frame_count = 1;
  bvh.values = {0, 1, 2, 10, 11, 12, 20, 21, 22, 30, 31, 32};
  const Bvh back = read_ok(write_bvh(bvh));
  ASSERT_EQ(back.joints.size(), 4u);
  EXPECT_EQ(back.joints[2].name, "a1");
  EXPECT_EQ(back.values, (std::vector<double>{0, 1, 2, 10, 11, 12, 30, 31, 32, 20, 21, 22}));
}

TEST(BvhWrite, NegativeZeroIsWrittenAsZero) {
  Bvh bvh = read_ok(kArm);
  bvh.values[3] = -1e-9;
  EXPECT_EQ(write_bvh(bvh).find("-0.000000"), std::string::npos);
}

// --- The malformed catalogue: every file gives ok == false, the line, and a clear message. ---

struct Malformed {
  const char* what;
  std::string text;
  int line;
  const char* fragment;  // must appear in the message
};

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

std::vector<Malformed> catalogue() {
  const std::string arm = kArm;
  const std::string header_only = arm.substr(0, arm.find("MOTION"));
  return {
      {"empty file", "", 1, "empty file"},
      {"not a BVH", "hello world\n", 1, "expected 'HIERARCHY'"},
      {"truncated in the hierarchy", arm.substr(0, arm.find("\t\tJOINT RightForeArm") + 20), 10,
       "unexpected end of file"},
      {"truncated before MOTION", header_only, 30, "unexpected end of file"},
      {"truncated motion (frame count mismatch: fewer)", arm.substr(0, arm.find("1.5 91.0")), 33,
       "truncated"},
      {"truncated mid-frame", arm.substr(0, arm.find("-20 -30")), 34, "has 4 values"},
      {"more frames than declared", replace(arm, "Frames: 2", "Frames: 1"), 34, "more frame lines"},
      {"frame with an extra value", replace(arm, "5 -5 15\n", "5 -5 15 7\n"), 33,
       "more than the 15 values"},
      {"CHANNELS count 4", replace(arm, "CHANNELS 3 Xrotation", "CHANNELS 4 Xrotation"), 9,
       "declares 4 channels"},
      {"CHANNELS count says 6, lists 3",
       replace(arm, "CHANNELS 3 Yrotation", "CHANNELS 6 Yrotation"), 14,
       "lists 3 channel names, then 'End'"},
      {"CHANNELS count says 3, lists 4",
       replace(arm, "CHANNELS 3 Zrotation Yrotation Xrotation",
               "CHANNELS 3 Zrotation Yrotation Xrotation Xposition"),
       23, "more channel names"},
      {"unknown channel name",
       replace(arm, "Yrotation Zrotation Xrotation", "Yrotation Zrotation Wrotation"), 13,
       "'Wrotation'"},
      {"channel listed twice",
       replace(arm, "Xrotation Yrotation Zrotation", "Xrotation Yrotation Yrotation"), 9,
       "listed twice"},
      {"no rotation channels",
       replace(arm, "CHANNELS 3 Xrotation Yrotation Zrotation",
               "CHANNELS 3 Xposition Yposition Zposition"),
       9, "all three rotation channels"},
      {"NaN in OFFSET", replace(arm, "OFFSET -27.0", "OFFSET nan"), 12, "not a finite number"},
      {"NaN in motion", replace(arm, "1.5 91.0", "1.5 NaN"), 34, "not a finite number"},
      {"inf in motion", replace(arm, "45 0 0 5", "45 0 inf 5"), 33, "not a finite number"},
      {"overflowing number", replace(arm, "OFFSET 0 60 0", "OFFSET 0 1e999 0"), 22,
       "not a finite number"},
      {"huge number", replace(arm, "1.0 90.0", "1.0 9e12"), 33, "too large"},
      {"huge OFFSET", replace(arm, "OFFSET 0 20 0", "OFFSET 0 2e7 0"), 26, "too large"},
      {"garbage number", replace(arm, "OFFSET -15.0 40.0", "OFFSET -15.0 4O.0"), 8,
       "expected a number"},
      {"unknown keyword in a joint",
       replace(arm, "\t\tOFFSET -27.0", "\t\tSCALE 1 1 1\n\t\t\tOFFSET -27.0"), 12,
       "unknown keyword 'SCALE'"},
      {"unknown keyword in HIERARCHY", replace(arm, "MOTION", "}\nMOTION"), 30,
       "unknown keyword '}'"},
      {"missing opening brace", replace(arm, "JOINT Head\n\t{", "JOINT Head\n"), 22,
       "expected '{'"},
      {"missing closing brace", replace(arm, "\t}\n}\nMOTION", "\t}\nMOTION"), 29,
       "missing '}' closing joint 'Hips'"},
      {"missing MOTION", replace(arm, "MOTION\n", ""), 30, "expected 'ROOT' or 'MOTION'"},
      {"missing Frame Time", replace(arm, "Frame Time: 0.033333\n", ""), 32, "expected 'Frame'"},
      {"negative frame count", replace(arm, "Frames: 2", "Frames: -2"), 31,
       "non-negative whole number"},
      {"forged huge frame count", replace(arm, "Frames: 2", "Frames: 999999999999"), 31,
       "exceeds the limit"},
      {"zero frame time", replace(arm, "Frame Time: 0.033333", "Frame Time: 0"), 32,
       "must be positive"},
      {"duplicate joint name", replace(arm, "JOINT Head", "JOINT RightArm"), 20,
       "duplicate joint name"},
      {"no ROOT", "HIERARCHY\nMOTION\nFrames: 0\nFrame Time: 0.1\n", 2, "no ROOT"},
      {"missing OFFSET", replace(arm, "\t\t\tOFFSET -27.0 0.0 0.0\n", ""), 17, "has no OFFSET"},
      {"End without Site", replace(arm, "End Site\n\t\t\t{", "End\n\t\t\t{"), 15,
       "expected 'Site'"},
      {"binary garbage", std::string("HIERARCHY\nROOT \x01\x02\xff\n{\0\0", 22), 3,
       "'\\x01\\x02\\xff'"},
  };
}

TEST(BvhMalformed, CatalogueGivesLineAndClearMessage) {
  for (const Malformed& m : catalogue()) {
    const BvhReadResult r = read_bvh(m.text);
    EXPECT_FALSE(r.ok) << m.what;
    EXPECT_EQ(r.error.line, m.line) << m.what << ": " << r.error.format();
    EXPECT_NE(r.error.message.find(m.fragment), std::string::npos)
        << m.what << ": " << r.error.format();
  }
}

TEST(BvhMalformed, EveryPrefixOfAValidFileFailsCleanlyOrParses) {
  // Truncation at every byte: never a crash (ASan/UBSan run this too), always a line number.
  const std::string arm = kArm;
  for (std::size_t n = 0; n < arm.size(); ++n) {
    const BvhReadResult r = read_bvh(std::string_view(arm).substr(0, n));
    if (!r.ok) {
      EXPECT_GE(r.error.line, 1) << n;
      EXPECT_FALSE(r.error.message.empty()) << n;
    }
  }
}

TEST(BvhMalformed, RandomByteMutationsNeverCrash) {
  // Hostile input: flip, insert or delete bytes at random. Every result is either a parse or an
  // error inside the file's line range (ASan/UBSan run this too).
  const std::string arm = kArm;
  const int lines = 1 + static_cast<int>(std::count(arm.begin(), arm.end(), '\n'));
  std::mt19937 rng(99);
  const char alphabet[] =
      "{}\n\t -.0123456789eEnaifJOINTEndSiteCHANNELS3 6XYZrotationposition:\0\xff";
  for (int i = 0; i < 3000; ++i) {
    std::string text = arm;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = rng() % text.size();
      const char c = alphabet[rng() % (sizeof alphabet - 1)];
      switch (rng() % 3) {
        case 0:
          text[at] = c;
          break;
        case 1:
          text.insert(at, 1, c);
          break;
        default:
          text.erase(at, 1 + rng() % 8);
          break;
      }
    }
    const BvhReadResult r = read_bvh(text);
    if (!r.ok) {
      EXPECT_GE(r.error.line, 1);
      EXPECT_LE(r.error.line, lines + 8);
      EXPECT_FALSE(r.error.message.empty());
    } else {
      EXPECT_EQ(r.bvh.values.size(),
                std::size_t(r.bvh.frame_count) * std::size_t(r.bvh.channel_count()));
    }
  }
}

std::string nested_chain(int depth) {
  std::string text = "HIERARCHY\n";
  for (int i = 0; i < depth; ++i) {
    text += (i == 0 ? "ROOT j" : "JOINT j") + std::to_string(i) +
            "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  }
  for (int i = 0; i < depth; ++i) text += "}\n";
  text += "MOTION\nFrames: 1\nFrame Time: 0.1\n";
  for (int i = 0; i < depth; ++i) text += "0 0 0 ";
  return text + "\n";
}

TEST(BvhLimits, DeepChainUpToTheJointLimitParses) {
  // 1024 nested joints: the recursive parser's depth is bounded by the joint limit.
  const BvhReadResult r = read_bvh(nested_chain(Bvh::kMaxJoints));
  ASSERT_TRUE(r.ok) << r.error.format();
  EXPECT_EQ(r.bvh.joints.size(), std::size_t(Bvh::kMaxJoints));
  EXPECT_EQ(r.bvh.joints.back().parent, Bvh::kMaxJoints - 2);
}

TEST(BvhLimits, OneJointMoreIsRefusedWithItsLine) {
  const BvhReadResult r = read_bvh(nested_chain(Bvh::kMaxJoints + 1));
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error.line, 2 + 4 * Bvh::kMaxJoints);  // the name of joint 1025
  EXPECT_NE(r.error.message.find("more than 1024 joints"), std::string::npos) << r.error.format();
}

TEST(BvhMalformed, ErrorFormatsWithLine) {
  const BvhReadResult r = read_bvh("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0\n");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.error.format().rfind("line ", 0), 0u) << r.error.format();
}

}  // namespace
}  // namespace sw::skeleton
