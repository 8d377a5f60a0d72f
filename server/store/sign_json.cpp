// Strict JSON reading and the API's JSON shapes (see sign_json.h).
#include "store/sign_json.h"

#include <algorithm>
#include <string>

#include "store/api_error.h"
#include "store/utf8_text.h"

namespace sw::store {
namespace {

using nlohmann::json;

struct DepthExceeded {};

// Line and column (1-based, column in code points) of a byte offset, for error messages a person
// can find in an editor.
json position_detail(std::string_view text, std::size_t offset) {
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      column = 1;
    } else if ((c & 0xC0) != 0x80) {
      ++column;
    }
  }
  return json{{"offset", offset}, {"line", line}, {"column", column}};
}

const char* type_name(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "boolean";
    case json::value_t::string: return "string";
    case json::value_t::array: return "array";
    case json::value_t::object: return "object";
    case json::value_t::binary: return "binary";
    case json::value_t::discarded: return "discarded";
    default: return "number";
  }
}

[[noreturn]] void wrong_type(const std::string& field, const char* expected, const json& value) {
  throw ApiError(400, "field '" + field + "' must be " + expected + ", not " + type_name(value),
                 json{{"field", field}, {"expected", expected}, {"got", type_name(value)}});
}

[[noreturn]] void too_long(const std::string& field, std::size_t limit) {
  throw ApiError(400, "field '" + field + "' is longer than " + std::to_string(limit) + " bytes",
                 json{{"field", field}, {"limit_bytes", limit}});
}

void reject_unknown_fields(const json& object, std::initializer_list<const char*> known,
                           const std::string& prefix) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool found = std::any_of(known.begin(), known.end(),
                             [&](const char* name) { return it.key() == name; });
    if (!found) {
      std::string field = prefix + it.key();
      throw ApiError(400, "unknown field '" + field + "'", json{{"field", field}});
    }
  }
}

std::string read_string(const json& object, const char* name, std::size_t limit, bool required,
                        bool allow_empty = false) {
  auto it = object.find(name);
  if (it == object.end()) {
    if (required) {
      throw ApiError(400, std::string("missing required field '") + name + "'",
                     json{{"field", name}});
    }
    return {};
  }
  if (!it->is_string()) wrong_type(name, "a string", *it);
  const std::string& value = it->get_ref<const std::string&>();
  if (value.size() > limit) too_long(name, limit);
  if (required && !allow_empty && normalize_for_match(value).empty()) {
    throw ApiError(400, std::string("field '") + name + "' must not be empty", json{{"field", name}});
  }
  return value;
}

}  // namespace

json parse_json_document(std::string_view text) {
  std::size_t bad = find_invalid_utf8(text);
  if (bad != std::string_view::npos) {
    json detail = position_detail(text, bad);
    throw ApiError(400, "body is not valid UTF-8 (byte " + std::to_string(bad) + ")", detail);
  }
  // The callback sees the depth of every value; throwing from it stops the parse at once.
  json::parser_callback_t limit_depth = [](int depth, json::parse_event_t, json&) {
    if (depth > kMaxJsonDepth) throw DepthExceeded{};
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), limit_depth);
  } catch (const DepthExceeded&) {
    throw ApiError(400, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels",
                   json{{"limit_depth", kMaxJsonDepth}});
  } catch (const json::parse_error& error) {
    // nlohmann's byte is 1-based and points just past the offending character.
    std::size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    json detail = position_detail(text, offset);
    std::string what = error.what();
    auto colon = what.find("syntax error");
    std::string reason = colon != std::string::npos ? what.substr(colon) : what;
    throw ApiError(400, "malformed JSON: " + reason, detail);
  }
}

SignInput parse_sign_input(const json& object, bool require_language) {
  if (!object.is_object()) {
    throw ApiError(400, std::string("a sign must be a JSON object, not ") + type_name(object),
                   json{{"expected", "object"}, {"got", type_name(object)}});
  }
  reject_unknown_fields(object,
                        {"language", "gloss", "notation", "format", "tags", "keywords", "sense",
                         "description", "starter", "letter"},
                        "");
  SignInput input;
  if (object.contains("language") || require_language) {
    input.language = read_string(object, "language", kMaxLabelBytes, true);
  }
  input.gloss = read_string(object, "gloss", kMaxGlossBytes, true);
  input.notation = read_string(object, "notation", kMaxNotationBytes, true);
  if (object.contains("format")) input.format = read_string(object, "format", kMaxLabelBytes, true);
  input.sense = read_string(object, "sense", kMaxSenseBytes, false);
  input.description = read_string(object, "description", kMaxDescriptionBytes, false);
  if (auto it = object.find("starter"); it != object.end()) {
    if (!it->is_boolean()) wrong_type("starter", "a boolean", *it);
    input.starter = it->get<bool>();
  }

  if (auto it = object.find("tags"); it != object.end()) {
    if (!it->is_array()) wrong_type("tags", "an array of strings", *it);
    if (it->size() > kMaxTags) {
      throw ApiError(400, "field 'tags' has more than " + std::to_string(kMaxTags) + " entries",
                     json{{"field", "tags"}, {"limit", kMaxTags}});
    }
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& tag = (*it)[i];
      std::string field = "tags[" + std::to_string(i) + "]";
      if (!tag.is_string()) wrong_type(field, "a string", tag);
      if (tag.get_ref<const std::string&>().size() > kMaxLabelBytes) too_long(field, kMaxLabelBytes);
      if (normalize_for_match(tag.get_ref<const std::string&>()).empty()) {
        throw ApiError(400, "field '" + field + "' must not be empty", json{{"field", field}});
      }
      input.tags.push_back(tag.get<std::string>());
    }
  }

  if (auto it = object.find("keywords"); it != object.end()) {
    if (!it->is_array()) wrong_type("keywords", "an array of strings or {word, sense} objects", *it);
    if (it->size() > kMaxKeywords) {
      throw ApiError(400,
                     "field 'keywords' has more than " + std::to_string(kMaxKeywords) + " entries",
                     json{{"field", "keywords"}, {"limit", kMaxKeywords}});
    }
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& entry = (*it)[i];
      std::string field = "keywords[" + std::to_string(i) + "]";
      KeywordEntry keyword;
      if (entry.is_string()) {
        keyword.word = entry.get<std::string>();
      } else if (entry.is_object()) {
        reject_unknown_fields(entry, {"word", "sense"}, field + ".");
        auto word = entry.find("word");
        if (word == entry.end()) {
          throw ApiError(400, "missing required field '" + field + ".word'",
                         json{{"field", field + ".word"}});
        }
        if (!word->is_string()) wrong_type(field + ".word", "a string", *word);
        keyword.word = word->get<std::string>();
        if (auto sense = entry.find("sense"); sense != entry.end()) {
          if (!sense->is_string()) wrong_type(field + ".sense", "a string", *sense);
          keyword.sense = sense->get<std::string>();
          if (keyword.sense.size() > kMaxSenseBytes) too_long(field + ".sense", kMaxSenseBytes);
        }
      } else {
        wrong_type(field, "a string or a {word, sense} object", entry);
      }
      if (keyword.word.size() > kMaxLabelBytes) too_long(field, kMaxLabelBytes);
      if (normalize_for_match(keyword.word).empty()) {
        throw ApiError(400, "field '" + field + "' must not be empty", json{{"field", field}});
      }
      input.keywords.push_back(std::move(keyword));
    }
  }

  if (object.contains("letter")) {
    auto it = object.find("letter");
    if (!it->is_string()) wrong_type("letter", "a string", *it);
    std::string letter = it->get<std::string>();
    std::vector<char32_t> code_points = decode_utf8(letter);
    bool has_space = std::any_of(code_points.begin(), code_points.end(), is_space);
    if (code_points.empty() || code_points.size() > kMaxLetterCodePoints || has_space) {
      throw ApiError(400,
                     "field 'letter' must be 1 to " + std::to_string(kMaxLetterCodePoints) +
                         " characters without spaces",
                     json{{"field", "letter"}});
    }
    input.letter = letter;
  }
  return input;
}

Language parse_language(const json& object) {
  if (!object.is_object()) {
    throw ApiError(400, std::string("a language must be a JSON object, not ") + type_name(object),
                   json{{"expected", "object"}});
  }
  reject_unknown_fields(object, {"code", "name", "spoken", "alphabet_script"}, "");
  Language language;
  language.code = read_string(object, "code", kMaxLabelBytes, true);
  language.name = read_string(object, "name", kMaxLabelBytes, true);
  language.spoken = read_string(object, "spoken", kMaxLabelBytes, true);
  language.alphabet_script = read_string(object, "alphabet_script", kMaxLabelBytes, false);
  return language;
}

json sign_content_json(const SignRecord& sign) {
  json keywords = json::array();
  for (const KeywordEntry& keyword : sign.keywords) {
    keywords.push_back(json{{"word", keyword.word}, {"sense", keyword.sense}});
  }
  json out{{"language", sign.language}, {"gloss", sign.gloss},     {"notation", sign.notation},
           {"format", sign.format},     {"tags", sign.tags},       {"keywords", keywords},
           {"sense", sign.sense},       {"description", sign.description},
           {"starter", sign.starter}};
  out["letter"] = sign.letter ? json(*sign.letter) : json(nullptr);
  return out;
}

json sign_to_json(const SignRecord& sign) {
  json out = sign_content_json(sign);
  out["id"] = sign.id;
  out["revision"] = sign.revision;
  out["created_at"] = sign.created_at;
  out["updated_at"] = sign.updated_at;
  if (sign.compiled) {
    json compiled = json::parse(*sign.compiled, nullptr, false);
    out["compiled"] = compiled.is_discarded() ? json(nullptr) : compiled;
  } else {
    out["compiled"] = nullptr;
  }
  if (sign.deleted) out["deleted"] = true;
  return out;
}

json language_to_json(const Language& language) {
  return json{{"code", language.code},
              {"name", language.name},
              {"spoken", language.spoken},
              {"alphabet_script", language.alphabet_script}};
}

json revision_to_json(const RevisionRecord& revision) {
  json snapshot = json::parse(revision.snapshot, nullptr, false);
  return json{{"sign_id", revision.sign_id},   {"revision", revision.revision},
              {"op", revision.op},             {"author", revision.author},
              {"at", revision.at},             {"notation", revision.notation},
              {"format", revision.format},
              {"snapshot", snapshot.is_discarded() ? json(nullptr) : snapshot}};
}

}  // namespace sw::store
