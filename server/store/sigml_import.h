// Importing a SiGML collection as published by SiGML projects: a folder of .sigml files, each
// holding one sign or many (hns_sign = H-SiGML, hamgestural_sign = G-SiGML), into one sign
// language of the store. `signweave import DIR --lang CODE` (cli/import_command.cpp).
//
// Each sign element is stored as written (wrapped in its own <sigml> document), validated like
// every sign the store takes (parse, then synthesis). Its gloss is the element's gloss attribute;
// an element without one takes the file's name ("HOUSE.sigml" -> HOUSE), and the n-th such
// element of a file "HOUSE#n" from the second on. The report is per file.
#pragma once

#include <string>
#include <vector>

#include "store/store.h"

namespace sw::store {

struct SigmlFileReport {
  std::string file;     // the path as found
  int signs = 0;        // sign elements found (and documents that failed before any was found: 0)
  ImportReport import;  // created / updated / unchanged, and each rejected sign with its reason
};

// A .sigml file, or a directory that holds .sigml files and no languages.json (a data/ tree).
bool is_sigml_collection(const std::string& path);

// Reads one file's signs into import items and returns how many sign elements it holds; an
// element that does not parse, or a file that is not SiGML, becomes a rejection (with the line of
// the element; 0 for the whole file) instead.
int read_sigml_file(const std::string& path, const std::string& text, const std::string& language,
                    std::vector<ImportItem>* items, std::vector<ImportRejection>* rejected);

// Imports every .sigml file of `path` (a file, or a directory's files in name order), each file
// in its own transaction with `mode`.
std::vector<SigmlFileReport> import_sigml_collection(Store& store, const std::string& path,
                                                     const std::string& language,
                                                     const std::string& author, ImportMode mode);

}  // namespace sw::store
