// Name tables of SignSpec's enums (see sign_spec_names.h). The order of each table is the enum's.
#include "notation/sign_spec_names.h"

#include <iterator>
#include <string>

namespace sw::notation {
namespace {

constexpr const char* kLevels[] = {
    "above_head", "head_top", "head",      "forehead", "eyebrows", "eyes",       "nose",
    "ears",       "cheeks",   "mouth",     "lips",     "teeth",    "tongue",     "chin",
    "under_chin", "neck",     "shoulders", "shoulder_top", "chest", "stomach",   "belly",
    "waist",      "below_waist", "neutral"};
constexpr const char* kSides[] = {"right_beside", "right", "centre", "left", "left_beside"};
constexpr const char* kContacts[] = {"none",  "close",    "touch", "arm_extended", "brush",
                                     "grasp", "between", "interlock", "cross", "behind"};
constexpr const char* kPlaces[] = {"palm", "back", "thumb_side", "little_side", "tip", "pad",
                                   "nail", "base", "middle_joint", "side", "wrist", "wrist_back",
                                   "forearm", "forearm_back", "elbow", "upper_arm", "thumb_ball",
                                   "elbow_inside"};
constexpr const char* kKinds[] = {"straight", "arc",   "circle", "ellipse",     "wavy",
                                  "zigzag",   "spiral", "fingerplay", "nod",     "swing",
                                  "twist",    "wristcircle", "replace", "to"};
constexpr const char* kSizes[] = {"normal", "small", "large"};
constexpr const char* kManners[] = {"normal", "fast", "slow", "tense", "halt", "rest"};
constexpr const char* kRepeats[] = {"none", "fromstart", "continuing", "reverse",
                                    "fromstart_several", "continuing_several"};
constexpr const char* kSymmetries[] = {"none", "lr", "lrud", "lrio", "par", "parud", "pario"};
constexpr const char* kLocationKinds[] = {"body", "neutral", "hand"};
constexpr const char* kSeedPalms[] = {"none", "D1", "D2", "D3", "D4", "D5"};

template <typename E, std::size_t N>
const char* lookup(const char* const (&table)[N], E v) {
  const auto i = static_cast<std::size_t>(v);
  return i < N ? table[i] : "?";
}
template <typename E, std::size_t N>
bool reverse(const char* const (&table)[N], std::string_view s, E* v) {
  for (std::size_t i = 0; i < N; ++i) {
    if (s == table[i]) {
      *v = static_cast<E>(i);
      return true;
    }
  }
  return false;
}
template <std::size_t N>
std::string join(const char* const (&table)[N]) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) out += (i ? ", " : "") + std::string(table[i]);
  return out;
}

}  // namespace

const char* name_of(BodyLevel v) { return lookup(kLevels, v); }
const char* name_of(Side v) { return lookup(kSides, v); }
const char* name_of(Contact v) { return lookup(kContacts, v); }
const char* name_of(HandPlace v) { return lookup(kPlaces, v); }
const char* name_of(MovementKind v) { return lookup(kKinds, v); }
const char* name_of(Size v) { return lookup(kSizes, v); }
const char* name_of(Manner v) { return lookup(kManners, v); }
const char* name_of(RepeatKind v) { return lookup(kRepeats, v); }
const char* name_of(Symmetry v) { return lookup(kSymmetries, v); }
const char* name_of(Location::Kind v) { return lookup(kLocationKinds, v); }
const char* name_of(SeedPalm v) { return lookup(kSeedPalms, v); }

bool from_name(std::string_view s, BodyLevel* v) { return reverse(kLevels, s, v); }
bool from_name(std::string_view s, Side* v) { return reverse(kSides, s, v); }
bool from_name(std::string_view s, Contact* v) { return reverse(kContacts, s, v); }
bool from_name(std::string_view s, HandPlace* v) { return reverse(kPlaces, s, v); }
bool from_name(std::string_view s, MovementKind* v) { return reverse(kKinds, s, v); }
bool from_name(std::string_view s, Size* v) { return reverse(kSizes, s, v); }
bool from_name(std::string_view s, Manner* v) { return reverse(kManners, s, v); }
bool from_name(std::string_view s, RepeatKind* v) { return reverse(kRepeats, s, v); }
bool from_name(std::string_view s, Symmetry* v) { return reverse(kSymmetries, s, v); }
bool from_name(std::string_view s, Location::Kind* v) { return reverse(kLocationKinds, s, v); }
bool from_name(std::string_view s, SeedPalm* v) { return reverse(kSeedPalms, s, v); }

template <> std::string names_list<BodyLevel>() { return join(kLevels); }
template <> std::string names_list<Side>() { return join(kSides); }
template <> std::string names_list<Contact>() { return join(kContacts); }
template <> std::string names_list<HandPlace>() { return join(kPlaces); }
template <> std::string names_list<MovementKind>() { return join(kKinds); }
template <> std::string names_list<RepeatKind>() { return join(kRepeats); }
template <> std::string names_list<Symmetry>() { return join(kSymmetries); }

}  // namespace sw::notation
