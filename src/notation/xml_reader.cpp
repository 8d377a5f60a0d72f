// The small XML reader (see xml_reader.h): recursive descent over the text, errors as values.
#include "notation/xml_reader.h"

#include "notation/text_position.h"

namespace sw::notation {
namespace {

bool name_start(unsigned char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' || c >= 0x80;
}
bool name_char(unsigned char c) {
  return name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}
bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

class XmlParser {
 public:
  XmlParser(std::string_view text, std::vector<Diagnostic>* diagnostics)
      : t_(text), index_(text), diags_(diagnostics) {}

  bool document(XmlElement* root) {
    if (t_.substr(0, 3) == "\xEF\xBB\xBF") p_ = 3;  // byte order mark
    if (!misc()) return false;
    if (p_ >= t_.size() || t_[p_] != '<') return fail(p_, "expected the document's root element '<...>', found " + found());
    if (!element(root, 0)) return false;
    if (!misc()) return false;
    if (p_ < t_.size()) return fail(p_, "expected the end of the document after the root element, found " + found());
    return true;
  }

 private:
  bool fail(std::size_t at, const std::string& message) {
    std::string symbol;
    if (at < t_.size()) {
      std::size_t e = at;
      decode_utf8(t_, &e);
      symbol = std::string(t_.substr(at, e - at));
    }
    diags_->push_back(index_.make(at, symbol.size(), symbol, message));
    return false;
  }
  std::string found() const {
    if (p_ >= t_.size()) return "the end of the document";
    std::size_t e = p_;
    decode_utf8(t_, &e);
    return "'" + std::string(t_.substr(p_, e - p_)) + "'";
  }
  bool starts(std::string_view s) const { return t_.substr(p_, s.size()) == s; }
  void skip_space() {
    while (p_ < t_.size() && space(t_[p_])) ++p_;
  }

  // Comments, processing instructions, the XML declaration and a DOCTYPE between elements.
  bool misc() {
    for (;;) {
      skip_space();
      if (starts("<!--")) {
        if (!comment()) return false;
      } else if (starts("<?")) {
        const std::size_t start = p_;
        const std::size_t end = t_.find("?>", p_ + 2);
        if (end == std::string_view::npos) return fail(start, "expected '?>' to end the processing instruction, found the end of the document");
        p_ = end + 2;
      } else if (starts("<!DOCTYPE")) {
        const std::size_t start = p_;
        int bracket = 0;
        while (p_ < t_.size() && !(t_[p_] == '>' && bracket == 0)) {
          if (t_[p_] == '[') ++bracket;
          if (t_[p_] == ']') --bracket;
          ++p_;
        }
        if (p_ >= t_.size()) return fail(start, "expected '>' to end the DOCTYPE, found the end of the document");
        ++p_;
      } else {
        return true;
      }
    }
  }

  bool comment() {
    const std::size_t start = p_;
    const std::size_t end = t_.find("-->", p_ + 4);
    if (end == std::string_view::npos) return fail(start, "expected '-->' to end the comment, found the end of the document");
    p_ = end + 3;
    return true;
  }

  bool name(std::string* out) {
    if (p_ >= t_.size() || !name_start(static_cast<unsigned char>(t_[p_]))) {
      return fail(p_, "expected a name, found " + found());
    }
    const std::size_t start = p_;
    while (p_ < t_.size() && name_char(static_cast<unsigned char>(t_[p_]))) ++p_;
    *out = std::string(t_.substr(start, p_ - start));
    return true;
  }

  // Decodes &...; at p_ (which is at '&') and appends it.
  bool entity(std::string* out) {
    const std::size_t start = p_;
    const std::size_t semi = t_.find(';', p_);
    if (semi == std::string_view::npos || semi - p_ > 12) {
      return fail(start, "expected an entity such as &amp; or &#65; ending in ';', found " + found());
    }
    const std::string_view e = t_.substr(p_ + 1, semi - p_ - 1);
    p_ = semi + 1;
    if (e == "lt") *out += '<';
    else if (e == "gt") *out += '>';
    else if (e == "amp") *out += '&';
    else if (e == "quot") *out += '"';
    else if (e == "apos") *out += '\'';
    else if (e.size() >= 2 && e[0] == '#') {
      const bool hex = e[1] == 'x' || e[1] == 'X';
      unsigned long v = 0;
      const std::string_view digits = e.substr(hex ? 2 : 1);
      if (digits.empty()) return fail(start, "expected digits in the character reference '&" + std::string(e) + ";'");
      for (char c : digits) {
        int d = -1;
        if (c >= '0' && c <= '9') d = c - '0';
        else if (hex && c >= 'a' && c <= 'f') d = c - 'a' + 10;
        else if (hex && c >= 'A' && c <= 'F') d = c - 'A' + 10;
        if (d < 0) return fail(start, "expected digits in the character reference '&" + std::string(e) + ";'");
        v = v * (hex ? 16 : 10) + static_cast<unsigned long>(d);
        if (v > 0x10FFFF) return fail(start, "expected a character reference up to U+10FFFF, found '&" + std::string(e) + ";'");
      }
      append_utf8(out, static_cast<char32_t>(v));
    } else {
      return fail(start, "expected a known entity (&lt; &gt; &amp; &quot; &apos; &#N;), found '&" + std::string(e) + ";'");
    }
    return true;
  }

  bool element(XmlElement* el, int depth) {
    if (depth >= kMaxXmlDepth) {
      return fail(p_, "elements nest deeper than " + std::to_string(kMaxXmlDepth) + " levels (the reader's limit)");
    }
    el->offset = p_;
    index_.locate(p_, &el->line, &el->column);
    ++p_;  // '<'
    if (!name(&el->name)) return false;
    // Attributes.
    for (;;) {
      const std::size_t before = p_;
      skip_space();
      if (starts("/>")) {
        p_ += 2;
        el->length = p_ - el->offset;
        el->closed = true;
        return true;
      }
      if (starts(">")) {
        ++p_;
        break;
      }
      if (p_ == before) return fail(p_, "expected whitespace, '>' or '/>' in the tag <" + el->name + ">, found " + found());
      XmlAttribute a;
      const std::size_t at = p_;
      if (!name(&a.name)) return false;
      for (const XmlAttribute& other : el->attributes) {
        if (other.name == a.name) return fail(at, "expected each attribute once in <" + el->name + ">, found '" + a.name + "' a second time");
      }
      skip_space();
      if (!starts("=")) return fail(p_, "expected '=' after the attribute name '" + a.name + "', found " + found());
      ++p_;
      skip_space();
      if (p_ >= t_.size() || (t_[p_] != '"' && t_[p_] != '\'')) {
        return fail(p_, "expected a quoted value for the attribute '" + a.name + "', found " + found());
      }
      const char quote = t_[p_++];
      const std::size_t value_start = p_;
      while (p_ < t_.size() && t_[p_] != quote) {
        if (t_[p_] == '&') {
          if (!entity(&a.value)) return false;
        } else if (t_[p_] == '<') {
          return fail(p_, "expected the closing quote of the attribute '" + a.name + "', found '<'");
        } else {
          a.value += t_[p_++];
        }
      }
      if (p_ >= t_.size()) return fail(value_start - 1, "expected the closing quote of the attribute '" + a.name + "', found the end of the document");
      ++p_;
      el->attributes.push_back(std::move(a));
    }
    el->length = p_ - el->offset;
    // Content.
    for (;;) {
      if (p_ >= t_.size()) {
        return fail(el->offset, "expected the end tag </" + el->name + ">, found the end of the document");
      }
      if (starts("</")) {
        const std::size_t at = p_;
        p_ += 2;
        std::string end_name;
        if (!name(&end_name)) return false;
        skip_space();
        if (!starts(">")) return fail(p_, "expected '>' to end </" + end_name + ">, found " + found());
        ++p_;
        if (end_name != el->name) {
          return fail(at, "expected the end tag </" + el->name + "> (the element opened at line " +
                              std::to_string(el->line) + "), found </" + end_name + ">");
        }
        el->closed = true;
        return true;
      }
      if (starts("<!--")) {
        if (!comment()) return false;
      } else if (starts("<![CDATA[")) {
        const std::size_t start = p_;
        const std::size_t end = t_.find("]]>", p_ + 9);
        if (end == std::string_view::npos) return fail(start, "expected ']]>' to end the CDATA section, found the end of the document");
        el->text += t_.substr(p_ + 9, end - p_ - 9);
        p_ = end + 3;
      } else if (starts("<?")) {
        const std::size_t start = p_;
        const std::size_t end = t_.find("?>", p_ + 2);
        if (end == std::string_view::npos) return fail(start, "expected '?>' to end the processing instruction, found the end of the document");
        p_ = end + 2;
      } else if (starts("<")) {
        el->children.emplace_back();
        if (!element(&el->children.back(), depth + 1)) return false;
      } else if (t_[p_] == '&') {
        if (!entity(&el->text)) return false;
      } else {
        el->text += t_[p_++];
      }
    }
  }

  std::string_view t_;
  std::size_t p_ = 0;
  LineIndex index_;
  std::vector<Diagnostic>* diags_;
};

}  // namespace

const std::string* XmlElement::attribute(std::string_view attribute_name) const {
  for (const XmlAttribute& a : attributes) {
    if (a.name == attribute_name) return &a.value;
  }
  return nullptr;
}

bool read_xml(std::string_view text, XmlElement* root, std::vector<Diagnostic>* diagnostics) {
  *root = XmlElement{};
  XmlParser parser(text, diagnostics);
  return parser.document(root);
}

std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

Diagnostic diagnostic_at(const XmlElement& e, std::string symbol, std::string message,
                         Severity severity) {
  return Diagnostic{severity, e.offset, e.length, e.line, e.column, std::move(symbol), std::move(message)};
}

}  // namespace sw::notation
