// A small XML reader for SiGML documents (no XML library is available here): elements,
// attributes, the five predefined entities and numeric character references, comments, CDATA,
// the XML declaration and processing instructions, a DOCTYPE (skipped). Every error is a
// Diagnostic with line and column; elements closed before an error are kept, so a reader can
// still take the complete signs of a damaged document.
//
// Does not: validate against a DTD, expand entities a DOCTYPE declares, handle namespaces (a
// prefixed name is just a name), or decode encodings other than UTF-8.
//
// Limit: elements nest at most kMaxXmlDepth deep, because the reader recurses per level and a
// hostile document must not exhaust the stack (the G-SiGML reader recurses along); SiGML nests
// fewer than 10 deep.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "notation/diagnostic.h"

namespace sw::notation {

constexpr int kMaxXmlDepth = 100;

struct XmlAttribute {
  std::string name;
  std::string value;  // entities decoded
};

struct XmlElement {
  std::string name;
  std::vector<XmlAttribute> attributes;
  std::vector<XmlElement> children;
  std::string text;        // character data directly inside (entities decoded, CDATA included)
  std::size_t offset = 0;  // byte offset of '<'
  std::size_t length = 0;  // bytes of the start tag
  int line = 1, column = 1;
  bool closed = false;     // its end tag (or '/>') was read: the element is complete

  // nullptr when absent.
  const std::string* attribute(std::string_view name) const;
};

// Reads `text`; `root` receives the document element (name empty when there is none). Returns
// true when the document is well-formed; otherwise `diagnostics` says where it is not.
bool read_xml(std::string_view text, XmlElement* root, std::vector<Diagnostic>* diagnostics);

// A diagnostic pointing at element `e`'s start tag (offset, length, line, column): how the SiGML
// readers report what was wrong and where, one definition so both report positions alike.
Diagnostic diagnostic_at(const XmlElement& e, std::string symbol, std::string message,
                         Severity severity = Severity::Error);

// Escapes text for an attribute value or character data (& < > " ').
std::string xml_escape(std::string_view text);

}  // namespace sw::notation
