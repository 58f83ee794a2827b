#include "sim/io/run_summary_reader.h"

#include <filesystem>
#include <fstream>

#include "sim/io/bounded_read.h"
#include "sim/io/json_fields.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

std::optional<json> read_run_summary(const std::string& run_dir) {
  namespace fs = std::filesystem;
  // It holds the final state of every node: a few MB for the largest rods.
  constexpr std::size_t kMaxSummaryBytes = std::size_t(64) << 20;
  std::error_code ec;
  const fs::path path = fs::path(run_dir) / "summary.json";
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  const std::string text = in ? io::read_at_most(in, kMaxSummaryBytes) : std::string();
  if (!in && !in.eof()) throw InputError(path.string() + ": cannot be read");
  if (text.size() > kMaxSummaryBytes) throw InputError(path.string() + ": larger than 64 MB: not a summary vascsim wrote");
  return io::parse_json_strictly(text, path.string());
}

bool summary_says_stopped(const nlohmann::json& summary) {
  if (!summary.is_object()) return false;
  const auto who = summary.find("stopped_by");
  return who != summary.end() && who->is_string() && !who->get<std::string>().empty();
}

}  // namespace vascsim
