// A stored sign written in another notation: GET /api/signs/{id}?format= and the page's export
// (docs/API.md). The sign's notation is parsed as stored and printed by the core's printers
// (src/notation/*_printer.cpp), so an export reads back as the same SignSpec wherever the
// printers round-trip (tests/native/notation/convert_round_trip_test.cpp has the shares).
#pragma once

#include <string>
#include <vector>

#include "store/sign_record.h"

namespace sw::store {

struct SignExport {
  std::string body;          // the document: a <sigml> file, or one `GLOSS = ...` line
  std::string content_type;  // application/xml or text/plain, UTF-8
  std::string file_name;     // for Content-Disposition: "<gloss>.sigml", "<gloss>.hamnosys.txt"
};

// The formats `format` may name: "sigml" (= H-SiGML, what CWASA/JASigning play), "hsigml",
// "gsigml", "hamnosys" (Unicode code points), "formula".
const std::vector<std::string>& export_formats();
// Throws ApiError 400 for a format not in export_formats(), 422 when the stored notation no
// longer parses (a sign stored before a parser change).
SignExport export_sign(const SignRecord& sign, const std::string& format);

}  // namespace sw::store
