// H-SiGML: hns_sign elements whose hamnosys_manual holds one element per HamNoSys symbol
// (<hamflathand/>), read through the HamNoSys reader with each element's position; and the
// document reader that dispatches sign elements of both SiGML kinds.
#include "notation/hamnosys.h"
#include "notation/hamnosys_symbols.h"
#include "notation/sigml.h"

namespace sw::notation {
namespace {

void collect_signs(const XmlElement& e, std::vector<SignParse>* out, int depth) {
  if (e.name == "hns_sign" || e.name == "hamgestural_sign") {
    if (!e.closed) return;  // cut off by a document error: reported by the XML reader
    out->push_back(e.name == "hns_sign" ? read_hns_sign(e) : read_hamgestural_sign(e));
    out->back().offset = e.offset;
    out->back().line = e.line;
    return;
  }
  if (depth > 3) return;  // signs sit directly in sigml / sigml_collection (or a wrapper)
  for (const XmlElement& c : e.children) collect_signs(c, out, depth + 1);
}

}  // namespace

SignParse read_hns_sign(const XmlElement& sign) {
  SignParse out;
  if (const std::string* g = sign.attribute("gloss")) out.gloss = *g;
  const XmlElement* manual = nullptr;
  SignSpec spec;
  spec.gloss = out.gloss;
  for (const XmlElement& c : sign.children) {
    if (c.name == "hamnosys_manual") {
      manual = &c;
    } else if (c.name == "hamnosys_nonmanual") {
      // Non-manual tiers in H-SiGML: mouth pictures are kept, other tiers read and skipped.
      for (const XmlElement& n : c.children) {
        if (const std::string* p = n.attribute("picture")) {
          spec.nonmanual.mouthing += (spec.nonmanual.mouthing.empty() ? "" : " ") + *p;
        }
      }
    } else {
      out.diagnostics.push_back(diagnostic_at(c, c.name, "expected hamnosys_manual or hamnosys_nonmanual in hns_sign, found <" + c.name + ">", Severity::Warning));
    }
  }
  if (!manual) {
    out.diagnostics.push_back(diagnostic_at(sign, "hns_sign", "expected a <hamnosys_manual> element in hns_sign, found none"));
    return out;
  }
  std::vector<HamSymbolRef> symbols;
  for (const XmlElement& c : manual->children) {
    const HamSymbolInfo* info = ham_symbol_by_name(c.name);
    if (!info) {
      out.diagnostics.push_back(diagnostic_at(c, c.name, "unknown HamNoSys symbol element <" + c.name + ">: expected a name such as hamflathand"));
      continue;
    }
    HamSymbolRef r;
    r.code = info->code;
    r.offset = c.offset;
    r.length = c.length;
    r.line = c.line;
    r.column = c.column;
    r.text = c.name;
    symbols.push_back(std::move(r));
  }
  if (symbols.empty()) {
    out.diagnostics.push_back(diagnostic_at(*manual, "hamnosys_manual", "expected HamNoSys symbol elements in hamnosys_manual, found none"));
    return out;
  }
  if (parse_hamnosys_symbols(symbols, manual->offset, &spec, &out.diagnostics)) out.spec = std::move(spec);
  return out;
}

std::vector<SignParse> parse_sigml_text(std::string_view text) {
  std::vector<SignParse> out;
  XmlElement root;
  std::vector<Diagnostic> xml_errors;
  read_xml(text, &root, &xml_errors);
  if (!root.name.empty()) collect_signs(root, &out, 0);
  if (!xml_errors.empty() || out.empty()) {
    SignParse document;  // diagnostics that belong to no sign
    document.diagnostics = std::move(xml_errors);
    if (document.diagnostics.empty()) {
      Diagnostic d;
      d.symbol = root.name;
      d.message = root.name.empty() ? "expected a SiGML document, found no element"
                                    : "expected hns_sign or hamgestural_sign elements in <" + root.name + ">, found none";
      document.diagnostics.push_back(d);
    }
    out.push_back(std::move(document));
  }
  return out;
}

std::string print_hns_sign(const SignSpec& sign, int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::string out = pad + "<hns_sign gloss=\"" + xml_escape(sign.gloss) + "\">\n";
  if (!sign.nonmanual.mouthing.empty()) {
    out += pad + "  <hamnosys_nonmanual>\n" + pad + "    <hnm_mouthpicture picture=\"" +
           xml_escape(sign.nonmanual.mouthing) + "\"/>\n" + pad + "  </hamnosys_nonmanual>\n";
  }
  out += pad + "  <hamnosys_manual>\n";
  for (char32_t c : hamnosys_symbols(sign)) out += pad + "    <" + ham_symbol_name(c) + "/>\n";
  out += pad + "  </hamnosys_manual>\n" + pad + "</hns_sign>\n";
  return out;
}

std::string print_hsigml(const std::vector<SignSpec>& signs) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<sigml>\n";
  for (const SignSpec& s : signs) out += print_hns_sign(s, 2);
  return out + "</sigml>\n";
}

}  // namespace sw::notation
