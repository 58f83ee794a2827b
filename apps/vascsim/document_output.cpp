#include "apps/vascsim/document_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

bool is_standard_output(const std::string& out) { return out == "-"; }

}  // namespace

void check_document_output(const std::string& out, bool overwrite, const std::vector<std::string>& inputs) {
  if (!is_standard_output(out)) check_replaceable_output(out, overwrite, inputs);
}

bool write_document_output(const std::string& out, const std::string& document) {
  if (!is_standard_output(out)) {
    write_file_atomically(out, document);
    return true;
  }
  // Flushed here, while errno still says why a write failed (a full disk, a closed pipe): a
  // document larger than the buffer fails inside fwrite, and the flush at exit no longer knows.
  errno = 0;
  const bool written = std::fwrite(document.data(), 1, document.size(), stdout) == document.size();
  if (!written || std::fflush(stdout) != 0) {
    const int error = errno;
    std::clearerr(stdout);
    throw InputError(std::string("cannot write to standard output (") +
                     (error ? std::strerror(error) : "write error") + ")");
  }
  return false;
}

}  // namespace vascsim::cli
