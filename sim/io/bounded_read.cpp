#include "sim/io/bounded_read.h"

#include <algorithm>

namespace vascsim::io {

std::string read_at_most(std::istream& in, std::size_t limit) {
  std::string text;
  char chunk[1 << 16];
  while (text.size() <= limit) {
    in.read(chunk, static_cast<std::streamsize>(sizeof chunk));
    const std::size_t got = static_cast<std::size_t>(in.gcount());
    text.append(chunk, std::min(got, limit + 1 - text.size()));
    if (got < sizeof chunk) break;  // the end, or an error the caller sees in in.bad()
  }
  return text;
}

}  // namespace vascsim::io
