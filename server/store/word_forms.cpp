// Hunspell behind WordForms (see word_forms.h).
#include "store/word_forms.h"

#include <hunspell/hunspell.hxx>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "store/utf8_text.h"

namespace sw::store {
namespace {

// Spoken language (ISO 639-1, languages.spoken) -> Hunspell dictionary name. The two spoken
// languages of the sign languages in data/.
struct DictionaryName {
  const char* spoken;
  const char* name;
};
constexpr DictionaryName kDictionaries[] = {{"en", "en_US"}, {"uk", "uk_UA"}};

std::string lower(const std::string& text) {
  std::string out;
  for (char32_t cp : decode_utf8(text)) append_utf8(out, to_lower(cp));
  return out;
}

}  // namespace

struct WordForms::Dictionary {
  std::string spoken;
  std::string aff_path;
  std::string dic_path;
  std::once_flag loaded;
  std::unique_ptr<Hunspell> hunspell;  // null when the files are missing
  std::mutex use;
};

WordForms& WordForms::shared() {
  static WordForms instance([] {
    const char* dir = std::getenv("SIGNWEAVE_HUNSPELL_DIR");
    return std::string(dir && *dir ? dir : SW_HUNSPELL_DICT_DIR);
  }());
  return instance;
}

WordForms::WordForms(std::string dictionary_dir) : dictionary_dir_(std::move(dictionary_dir)) {
  for (const DictionaryName& entry : kDictionaries) {
    auto dictionary = std::make_unique<Dictionary>();
    dictionary->spoken = entry.spoken;
    dictionary->aff_path = dictionary_dir_ + "/" + entry.name + ".aff";
    dictionary->dic_path = dictionary_dir_ + "/" + entry.name + ".dic";
    dictionaries_.push_back(std::move(dictionary));
  }
}

WordForms::~WordForms() = default;

WordForms::Dictionary* WordForms::dictionary_for(const std::string& spoken) {
  for (auto& dictionary : dictionaries_) {
    if (dictionary->spoken != spoken) continue;
    std::call_once(dictionary->loaded, [&] {
      std::error_code error;
      if (!std::filesystem::exists(dictionary->aff_path, error) ||
          !std::filesystem::exists(dictionary->dic_path, error)) {
        std::fprintf(stderr,
                     "signweave: no Hunspell dictionary %s: words in '%s' are matched as typed\n",
                     dictionary->dic_path.c_str(), spoken.c_str());
        return;
      }
      dictionary->hunspell =
          std::make_unique<Hunspell>(dictionary->aff_path.c_str(), dictionary->dic_path.c_str());
    });
    return dictionary->hunspell ? dictionary.get() : nullptr;
  }
  return nullptr;
}

bool WordForms::covers(const std::string& spoken) { return dictionary_for(spoken) != nullptr; }

std::vector<std::string> WordForms::stems(const std::string& spoken, const std::string& word) {
  Dictionary* dictionary = dictionary_for(spoken);
  if (dictionary == nullptr || word.empty()) return {};
  std::vector<std::string> found;
  {
    std::lock_guard<std::mutex> lock(dictionary->use);
    found = dictionary->hunspell->stem(word);
  }
  std::vector<std::string> out;
  for (const std::string& stem : found) {
    std::string form = lower(stem);
    if (form == word || decode_utf8(form).size() < kMinStemCodePoints) continue;
    if (std::find(out.begin(), out.end(), form) == out.end()) out.push_back(form);
  }
  return out;
}

}  // namespace sw::store
