#include <cstdio>
#include <string>
#include <vector>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "apps/vascsim/document_output.h"
#include "sim/io/scene_reader.h"
#include "sim/io/vessels_json.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec> kOptions = {
    {"scene", "FILE", "a scene with a \"vessels\" section (required)"},
    {"out", "FILE", "where to write the network JSON, or - for standard output (required)"},
    {"force", "", "overwrite FILE if it exists"},
    {"help", "", "show this help"},
};

void print_usage() {
  std::printf(
      "usage: vascsim vessels --scene FILE --out FILE [--force]\n\n"
      "Builds the scene's vessel network as a run would (the lumen as the union of its tubes and sacs, or\n"
      "traced from its image mask), routes it from start to goal and writes the lumen outline, walls,\n"
      "graph (or mask), route and reference trajectory as JSON (format in docs/environment.md).\n\noptions:\n%s",
      format_options(kOptions).c_str());
}

}  // namespace

int run_vessels_command(int argc, char** argv) {
  Args args(argc, argv, 2, kOptions);
  if (args.flag("help")) {
    print_usage();
    return 0;
  }
  if (!args.positional().empty()) throw UsageError("unexpected argument '" + args.positional().front() + "'");
  const auto scene_file = args.value("scene");
  if (!scene_file) throw UsageError("--scene FILE is required");
  const auto out = args.value("out");
  if (!out) throw UsageError("--out FILE is required");
  const Scene scene = read_scene_file(*scene_file);
  if (!scene.has_environment || scene.environment != EnvironmentKind::kVessels)
    throw UsageError("scene " + scene.file + " has no \"vessels\" section (for a maze use vascsim maze)");
  warn_unused_fields("vessels", scene);
  // Never replace the scene or the mask image it was made from, nor a device or pipe, even with --force.
  std::vector<std::string> inputs{scene.file};
  if (scene.vessels.from_mask) inputs.push_back(scene.vessels.mask.resolved);
  check_document_output(*out, args.flag("force"), inputs);
  if (!write_document_output(*out, vessels_document(scene))) return 0;
  std::printf("wrote %s (%s)\n", out->c_str(), scene.vessels.from_mask ? "traced from an image mask" : "vessel graph");
  return 0;
}

}  // namespace vascsim::cli
