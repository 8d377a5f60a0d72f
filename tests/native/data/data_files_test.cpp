// The default sign database sources (data/): every file is read and every sign parsed with the core,
// exactly as the server's import does. The data is in the repository, so nothing here is skipped —
// a missing file is a failure.
//
// Checks: JSON well-formed, the fields the server imports present and typed, every notation parses
// with no error into exactly one sign that prints back to the same sign, counts (33 Ukrainian
// letters, 26 ASL letters, ASL numbers 0–9 at least, at least 110 lexicon signs), glosses and letters
// unique, the seed's letters В and Г written exactly as seed 004 Table 2 and meaning what the seed
// says, letters with movement having one and held letters none, and lexicon spot checks that the
// formulas say what the descriptions say.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/formula.h"
#include "notation/parse.h"
#include "notation/sign_spec.h"

namespace {

using nlohmann::json;
using sw::notation::BodyLevel;
using sw::notation::Contact;
using sw::notation::Location;
using sw::notation::NotationFormat;
using sw::notation::SeedPalm;
using sw::notation::SignSpec;
using sw::notation::Symmetry;

std::string data_path(const std::string& relative) {
  return std::string(SIGNWEAVE_SOURCE_DIR) + "/data/" + relative;
}

// One line of a .jsonl file, with where it came from for failure messages.
struct Entry {
  std::string where;  // "ukl/alphabet.jsonl:3"
  json value;
};

// Reads a JSON-lines file; every non-empty line must be one JSON object.
std::vector<Entry> read_jsonl(const std::string& relative) {
  std::vector<Entry> entries;
  std::ifstream in(data_path(relative));
  EXPECT_TRUE(in.good()) << "cannot open data/" << relative;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = relative + ":" + std::to_string(number);
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      ADD_FAILURE() << where << ": empty line (a .jsonl file has one object a line)";
      continue;
    }
    json value = json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (value.is_discarded() || !value.is_object()) {
      ADD_FAILURE() << where << ": not a JSON object";
      continue;
    }
    entries.push_back({where, std::move(value)});
  }
  return entries;
}

std::string text_field(const Entry& e, const char* key) {
  const auto it = e.value.find(key);
  if (it == e.value.end() || !it->is_string() || it->get<std::string>().empty()) {
    ADD_FAILURE() << e.where << ": field \"" << key << "\" missing or not a non-empty string";
    return {};
  }
  return it->get<std::string>();
}

// The bodies of every `M(replace ...)` in a formula, parentheses balanced.
std::vector<std::string> replace_movements(const std::string& notation) {
  std::vector<std::string> bodies;
  for (std::size_t at = notation.find("M(replace"); at != std::string::npos;
       at = notation.find("M(replace", at + 1)) {
    int depth = 0;
    std::size_t end = at + 1;
    for (; end < notation.size(); ++end) {
      if (notation[end] == '(') ++depth;
      if (notation[end] == ')' && --depth == 0) break;
    }
    bodies.push_back(notation.substr(at, end - at + 1));
  }
  return bodies;
}

// A change of orientation replaces the whole orientation (SignSpec has no "unchanged" direction):
// `M(replace, P(o))` alone would also turn the fingers to the default E(uo). Data states both.
void expect_replace_states_full_orientation(const Entry& e, const std::string& notation) {
  for (const std::string& m : replace_movements(notation)) {
    const bool has_e = m.find("E(") != std::string::npos;
    const bool has_p = m.find("P(") != std::string::npos;
    EXPECT_EQ(has_e, has_p) << e.where << ": " << m << " changes orientation: give both E(...) and P(...)";
  }
}

// HamNoSys palm orientation is relative to the finger direction: synthesis turns the palm towards
// P within the plane across E, so P parallel to E (E(d), P(d)) says nothing and is a writing error.
bool parallel(const sw::notation::Direction& a, const sw::notation::Direction& b) {
  return a.y * b.z == a.z * b.y && a.z * b.x == a.x * b.z && a.x * b.y == a.y * b.x;
}
void expect_palm_across_fingers(const Entry& e, const char* what, const sw::notation::Orientation& o) {
  if (o.seed_palm != SeedPalm::None) return;  // the seed's D_i carry no finger direction
  EXPECT_FALSE(parallel(o.extended_finger, o.palm)) << e.where << ": " << what
      << ": the palm direction P(...) is parallel to the finger direction E(...)";
}
void expect_orientations_well_formed(const Entry& e, const SignSpec& sign) {
  expect_palm_across_fingers(e, "dominant hand", sign.dominant.orientation);
  if (sign.nondominant) expect_palm_across_fingers(e, "other hand", sign.nondominant->orientation);
  for (const auto& step : sign.movements) {
    for (const auto* hand : {&step.dominant, &step.nondominant}) {
      for (const auto& m : *hand) {
        if (m.to_orientation) expect_palm_across_fingers(e, "orientation change", *m.to_orientation);
      }
    }
  }
}

// Parses the entry's notation with the core; returns the one sign, or fails with the diagnostics.
SignSpec parse_entry(const Entry& e) {
  const std::string notation = text_field(e, "notation");
  EXPECT_EQ(text_field(e, "format"), "formula") << e.where;
  expect_replace_states_full_orientation(e, notation);
  const auto outcome = sw::notation::parse_notation(notation, NotationFormat::Formula);
  std::ostringstream why;
  for (const auto& d : outcome.diagnostics) why << "\n    " << sw::notation::format_diagnostic(d);
  EXPECT_TRUE(outcome.ok()) << e.where << ": " << notation << why.str();
  EXPECT_EQ(outcome.signs.size(), 1u) << e.where << ": " << notation << why.str();
  if (outcome.signs.empty()) return SignSpec{};
  expect_orientations_well_formed(e, outcome.signs.front());
  // The editor and the server print signs back: what the data says must survive the printer.
  const std::string printed = sw::notation::print_formula(outcome.signs.front());
  const auto reread = sw::notation::parse_notation(printed, NotationFormat::Formula);
  EXPECT_TRUE(reread.ok() && reread.signs.size() == 1u) << e.where << ": printed as " << printed;
  if (reread.signs.size() == 1u) {
    EXPECT_EQ(sw::notation::print_formula(reread.signs.front()), printed) << e.where;
  }
  return outcome.signs.front();
}

// Letters / digits files: letter + gloss + notation + description, letters and glosses unique.
std::map<std::string, SignSpec> check_letter_file(const std::string& relative,
                                                  std::set<std::string>* glosses) {
  std::map<std::string, SignSpec> by_letter;
  for (const Entry& e : read_jsonl(relative)) {
    const std::string letter = text_field(e, "letter");
    const std::string gloss = text_field(e, "gloss");
    text_field(e, "description");
    EXPECT_TRUE(glosses->insert(gloss).second) << e.where << ": duplicate gloss " << gloss;
    SignSpec sign = parse_entry(e);
    EXPECT_TRUE(by_letter.emplace(letter, std::move(sign)).second)
        << e.where << ": duplicate letter " << letter;
  }
  // Two letters of one alphabet that mean the same sign could not be told apart when spelled
  // (the canonical printed form compares every field of the model; without the H(...) words it
  // was written with, the hands print finger by finger, so two spellings of one shape compare equal).
  std::map<std::string, std::string> letter_of_form;
  for (const auto& [letter, sign] : by_letter) {
    SignSpec bare = sign;
    bare.dominant.shape.hamnosys_base.clear();
    for (auto& step : bare.movements) {
      for (auto& m : step.dominant) {
        if (m.to_shape) m.to_shape->hamnosys_base.clear();
      }
    }
    const auto [it, fresh] = letter_of_form.emplace(sw::notation::print_formula(bare), letter);
    EXPECT_TRUE(fresh) << relative << ": " << letter << " is the same sign as " << it->second;
  }
  return by_letter;
}

bool has_movement(const SignSpec& s) { return !s.movements.empty(); }

// ---------------------------------------------------------------------------------------------

TEST(DataFiles, LanguagesListsEveryLanguageFolderOnce) {
  std::ifstream in(data_path("languages.json"));
  ASSERT_TRUE(in.good()) << "cannot open data/languages.json";
  const json languages = json::parse(in, nullptr, /*allow_exceptions=*/false);
  ASSERT_FALSE(languages.is_discarded()) << "data/languages.json is not valid JSON";
  ASSERT_TRUE(languages.is_array());
  std::set<std::string> codes;
  for (const json& l : languages) {
    ASSERT_TRUE(l.is_object());
    for (const char* key : {"code", "name", "spoken", "alphabet_script"}) {
      ASSERT_TRUE(l.contains(key) && l[key].is_string() && !l[key].get<std::string>().empty())
          << "languages.json: " << l.dump() << " lacks \"" << key << "\"";
    }
    const std::string code = l["code"];
    EXPECT_TRUE(codes.insert(code).second) << "duplicate language code " << code;
    EXPECT_TRUE(std::ifstream(data_path(code + "/alphabet.jsonl")).good())
        << "language " << code << " has no data/" << code << "/alphabet.jsonl";
  }
  EXPECT_EQ(codes, (std::set<std::string>{"ase", "ukl"}));
}

TEST(DataFiles, UkrainianAlphabetHasAll33LettersAndParses) {
  std::set<std::string> glosses;
  const auto letters = check_letter_file("ukl/alphabet.jsonl", &glosses);
  const std::vector<std::string> expected = {"А", "Б", "В", "Г", "Ґ", "Д", "Е", "Є", "Ж", "З", "И",
                                             "І", "Ї", "Й", "К", "Л", "М", "Н", "О", "П", "Р", "С",
                                             "Т", "У", "Ф", "Х", "Ц", "Ч", "Ш", "Щ", "Ь", "Ю", "Я"};
  EXPECT_EQ(letters.size(), 33u);
  for (const auto& letter : expected) EXPECT_EQ(letters.count(letter), 1u) << "missing " << letter;
  // Letters drawn with a movement in the dactyl alphabet, and letters that are held still.
  for (const char* moving : {"Ґ", "Д", "З", "Й", "Ї", "Ц", "Щ"}) {
    ASSERT_EQ(letters.count(moving), 1u) << moving;
    EXPECT_TRUE(has_movement(letters.at(moving))) << moving;
  }
  for (const char* held : {"А", "В", "Г", "И", "О", "Ш", "Я"}) {
    ASSERT_EQ(letters.count(held), 1u) << held;
    EXPECT_FALSE(has_movement(letters.at(held))) << held;
  }
}

// Seed 004 Table 2 — kept byte for byte, and parsed to what the seed means (SOURCES.md §1).
TEST(DataFiles, SeedLettersVeAndHeAreTheSeedFormulas) {
  std::map<std::string, std::string> notation_of;
  for (const Entry& e : read_jsonl("ukl/alphabet.jsonl")) {
    notation_of[text_field(e, "letter")] = text_field(e, "notation");
  }
  EXPECT_EQ(notation_of["В"],
            "R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))");
  EXPECT_EQ(notation_of["Г"],
            "R(L1(0), D5, F_0^1(1), F_0^2(1), F_0^3(0), F_0^4(0), F_0^5(0))");

  const auto ve = sw::notation::parse_notation(notation_of["В"], NotationFormat::Formula);
  ASSERT_TRUE(ve.ok());
  ASSERT_EQ(ve.signs.size(), 1u);
  const auto& ve_hand = ve.signs[0].dominant;
  EXPECT_EQ(ve_hand.orientation.seed_palm, SeedPalm::D1);
  EXPECT_EQ(ve_hand.location.seed_id, 1);
  EXPECT_EQ(ve_hand.location.level, BodyLevel::Chest);
  EXPECT_EQ(ve_hand.location.contact, Contact::None);
  EXPECT_FLOAT_EQ(ve_hand.shape.fingers[0].t, 0.5f);  // thumb half straight
  for (int k = 1; k < 5; ++k) EXPECT_FLOAT_EQ(ve_hand.shape.fingers[k].t, 1.0f) << k;

  const auto he = sw::notation::parse_notation(notation_of["Г"], NotationFormat::Formula);
  ASSERT_TRUE(he.ok());
  ASSERT_EQ(he.signs.size(), 1u);
  const auto& he_hand = he.signs[0].dominant;
  EXPECT_EQ(he_hand.orientation.seed_palm, SeedPalm::D5);
  EXPECT_FLOAT_EQ(he_hand.shape.fingers[0].t, 1.0f);  // thumb straight
  EXPECT_FLOAT_EQ(he_hand.shape.fingers[1].t, 1.0f);  // index straight
  for (int k = 2; k < 5; ++k) EXPECT_FLOAT_EQ(he_hand.shape.fingers[k].t, 0.0f) << k;
}

TEST(DataFiles, AslAlphabetHas26LettersAndJAndZMove) {
  std::set<std::string> glosses;
  const auto letters = check_letter_file("ase/alphabet.jsonl", &glosses);
  EXPECT_EQ(letters.size(), 26u);
  for (char c = 'A'; c <= 'Z'; ++c) {
    const std::string letter(1, c);
    ASSERT_EQ(letters.count(letter), 1u) << "missing " << letter;
    const bool moves = (c == 'J' || c == 'Z');
    EXPECT_EQ(has_movement(letters.at(letter)), moves) << letter;
  }
  // Z is three strokes (right, diagonal down-left, right); J ends with the palm turned in.
  EXPECT_EQ(letters.at("Z").movements.size(), 3u);
  // G and H point sideways, P and Q down; the rest of the alphabet points up.
  EXPECT_EQ(letters.at("G").dominant.orientation.extended_finger.x, 1);  // signer's left
  EXPECT_EQ(letters.at("H").dominant.orientation.extended_finger.x, 1);
  EXPECT_EQ(letters.at("P").dominant.orientation.extended_finger.y, -1);
  EXPECT_EQ(letters.at("Q").dominant.orientation.extended_finger.y, -1);
  EXPECT_EQ(letters.at("A").dominant.orientation.extended_finger.y, 1);
}

TEST(DataFiles, AslDigitsCoverZeroToNine) {
  std::set<std::string> glosses;
  const auto digits = check_letter_file("ase/digits.jsonl", &glosses);
  EXPECT_GE(digits.size(), 10u);
  for (char c = '0'; c <= '9'; ++c) {
    const std::string digit(1, c);
    ASSERT_EQ(digits.count(digit), 1u) << "missing " << digit;
    EXPECT_FALSE(has_movement(digits.at(digit))) << digit << " is a held handshape";
  }
  ASSERT_EQ(digits.count("10"), 1u);
  EXPECT_TRUE(has_movement(digits.at("10"))) << "10 is made with a shake";
}

TEST(DataFiles, AslLexiconParsesWithUniqueGlossesAndKeywords) {
  std::map<std::string, SignSpec> by_gloss;
  std::set<std::string> alphabet_glosses;
  for (const auto* file : {"ase/alphabet.jsonl", "ase/digits.jsonl"}) {
    for (const Entry& e : read_jsonl(file)) alphabet_glosses.insert(text_field(e, "gloss"));
  }
  for (const Entry& e : read_jsonl("ase/lexicon.jsonl")) {
    const std::string gloss = text_field(e, "gloss");
    text_field(e, "sense");
    text_field(e, "description");
    const auto keywords = e.value.find("keywords");
    ASSERT_TRUE(keywords != e.value.end() && keywords->is_array() && !keywords->empty())
        << e.where << ": keywords must be a non-empty array";
    for (const json& k : *keywords) {
      EXPECT_TRUE(k.is_string() && !k.get<std::string>().empty()) << e.where << ": empty keyword";
    }
    const auto tags = e.value.find("tags");
    EXPECT_TRUE(tags != e.value.end() && tags->is_array() && !tags->empty())
        << e.where << ": tags must be a non-empty array";
    EXPECT_TRUE(e.value.value("starter", false)) << e.where << ": starter set entries say so";
    EXPECT_EQ(alphabet_glosses.count(gloss), 0u) << e.where << ": gloss used by a letter";
    SignSpec sign = parse_entry(e);
    EXPECT_TRUE(by_gloss.emplace(gloss, std::move(sign)).second)
        << e.where << ": duplicate gloss " << gloss;
  }
  EXPECT_GE(by_gloss.size(), 110u);

  // The vocabulary the issue asks the starter set to cover.
  for (const char* gloss :
       {"HELLO", "GOODBYE", "PLEASE", "THANK-YOU", "SORRY", "EXCUSE-ME", "WELCOME", "MOTHER",
        "FATHER", "SISTER", "BROTHER", "FAMILY", "BABY", "FRIEND", "MAN", "WOMAN", "BOY", "GIRL",
        "PERSON", "DEAF", "HEARING", "TEACHER", "STUDENT", "INTERPRETER", "NOW", "TODAY",
        "TOMORROW", "YESTERDAY", "TIME", "DAY", "WEEK", "MONTH", "YEAR", "MORNING", "NIGHT",
        "LATER", "BEFORE", "AFTER", "HOME", "SCHOOL", "WORK", "HOSPITAL", "STORE", "CHURCH",
        "WHERE", "WHO", "WHAT", "WHEN", "WHY", "HOW", "WHICH", "GO", "COME", "EAT", "DRINK",
        "SLEEP", "WANT", "NEED", "LIKE", "LOVE", "HELP", "KNOW", "UNDERSTAND", "LEARN", "SEE",
        "SIGN", "PLAY", "READ", "WRITE", "STOP", "FINISH", "WAIT", "GIVE", "HAVE", "CAN", "GOOD",
        "BAD", "HAPPY", "SAD", "BIG", "SMALL", "HOT", "COLD", "NEW", "OLD", "FINE", "TIRED",
        "SICK", "BEAUTIFUL", "YES", "NO", "NOT", "AGAIN", "MORE", "NAME", "MY", "YOUR", "ME",
        "YOU"}) {
    EXPECT_EQ(by_gloss.count(gloss), 1u) << "the starter lexicon lacks " << gloss;
  }
}

// Spot checks that formulas say what their descriptions say (a wrong level or a lost second hand
// would still parse).
TEST(DataFiles, AslLexiconFormulasMatchTheirDescriptions) {
  std::map<std::string, SignSpec> sign;
  for (const Entry& e : read_jsonl("ase/lexicon.jsonl")) {
    sign[text_field(e, "gloss")] = parse_entry(e);
  }
  const auto place = [&](const char* gloss) -> const Location& {
    return sign[gloss].dominant.location;
  };
  // MOTHER: thumb on the chin; FATHER: thumb on the forehead; both touch.
  EXPECT_EQ(place("MOTHER").level, BodyLevel::Chin);
  EXPECT_EQ(place("MOTHER").contact, Contact::Touch);
  EXPECT_EQ(place("FATHER").level, BodyLevel::Forehead);
  EXPECT_EQ(place("FATHER").contact, Contact::Touch);
  ASSERT_TRUE(place("MOTHER").contact_part.has_value());
  EXPECT_EQ(place("MOTHER").contact_finger, 0);  // the thumb (Finger::Thumb)
  // Two-handed signs with a base hand have a non-dominant hand; symmetric ones a symmetry.
  for (const char* based : {"SCHOOL", "WORK", "TIME", "HELP", "WEEK", "READ", "NAME"}) {
    EXPECT_TRUE(sign[based].nondominant.has_value()) << based;
    EXPECT_EQ(place(based).kind, Location::Kind::OtherHand) << based;
  }
  // STOP starts in space and ends with a chop onto the other palm: the contact is the target.
  ASSERT_FALSE(sign["STOP"].movements.empty());
  ASSERT_FALSE(sign["STOP"].movements.front().dominant.empty());
  const auto& chop = sign["STOP"].movements.front().dominant.front();
  ASSERT_TRUE(chop.to_location.has_value());
  EXPECT_EQ(chop.to_location->kind, Location::Kind::OtherHand);
  EXPECT_EQ(chop.to_location->contact, Contact::Touch);
  for (const char* symmetric : {"PERSON", "NOW", "WANT", "FINISH", "CAN", "SAD", "BIG"}) {
    EXPECT_NE(sign[symmetric].symmetry, Symmetry::None) << symmetric;
  }
  // Movement and repetition where the sign has them, none where it is held.
  for (const char* moving : {"HELLO", "THANK-YOU", "GO", "COME", "SEE", "FINISH", "WANT"}) {
    EXPECT_FALSE(sign[moving].movements.empty()) << moving;
  }
  for (const char* held : {"MY", "LOVE", "THINK", "ME"}) {
    EXPECT_TRUE(sign[held].movements.empty()) << held;
  }
  for (const char* repeated : {"MOTHER", "SCHOOL", "TIME", "WORK", "YES"}) {
    EXPECT_NE(sign[repeated].repetition.kind, sw::notation::RepeatKind::None) << repeated;
  }
  // Non-manuals only where they belong to the sign.
  EXPECT_EQ(sign["NO"].nonmanual.head, "shake");
  EXPECT_EQ(sign["YES"].nonmanual.head, "nod");
  EXPECT_EQ(sign["WHERE"].nonmanual.eyebrows, "down");
  EXPECT_EQ(sign["HAPPY"].nonmanual.expression, "happy");
  EXPECT_TRUE(sign["HELLO"].nonmanual.head.empty());
}

}  // namespace
