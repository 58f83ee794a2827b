// Reading an input file whose size the reader caps (a scene, a sweep file): the stream's bytes up
// to one past the cap, so that the caller can tell a file over its limit from one at it, read in
// chunks so that the cap costs nothing. A buffer of the cap, filled by one read, cost every
// `vascsim run` 16 MB of zeroed memory (4,000 page faults, 17 M instructions) for a 2 kB scene.
#pragma once

#include <cstddef>
#include <istream>
#include <string>

namespace vascsim::io {

// At most limit + 1 bytes of `in` (limit < SIZE_MAX), from its position to its end. Sets in's badbit on a read
// error, as istream::read does; the caller checks it.
std::string read_at_most(std::istream& in, std::size_t limit);

}  // namespace vascsim::io
