// --out of the commands that write one JSON document (maze, vessels): a file, written so that it
// is never half there and never replaces what the user did not ask to replace, or "-" for
// standard output, as Unix tools read it (`vascsim maze --out - | jq .path`; a file named "-" is
// "./-").
#pragma once

#include <string>
#include <vector>

namespace vascsim::cli {

// Before the work that makes the document: for a file, check_replaceable_output (it must not
// exist without --force, nor be a device, a directory or one of `inputs`).
void check_document_output(const std::string& out, bool overwrite, const std::vector<std::string>& inputs);
// Writes the document. Returns false if it went to standard output, where nothing else may be
// printed.
bool write_document_output(const std::string& out, const std::string& document);

}  // namespace vascsim::cli
