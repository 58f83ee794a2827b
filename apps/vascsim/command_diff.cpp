// vascsim diff A.png B.png: image comparison for golden-image regression (render/image_diff.h).
// Exit 0 when no pixel differs by more than the tolerance, 1 otherwise, 2 on bad input.
// Built only with the renderer (VASCSIM_RENDER=ON); the file is globbed into the app either way.
#ifdef VASCSIM_HAVE_RENDER
#include <cmath>
#include <cstdio>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "sim/io/png_file.h"
#include "render/image_diff.h"
#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec>& diff_options() {
  static const std::vector<OptionSpec> options = {
      {"tolerance", "T", "largest per-channel difference (0..255) a pixel may have (default 0)"},
      {"max-pixels", "N", "number of pixels allowed over the tolerance (default 0)"},
      {"out", "FILE", "write a heat map of the differences as PNG"},
      {"force", "", "replace an existing --out file (never an input, never a non-regular file)"},
      {"help", "", "show this help"},
  };
  return options;
}

}  // namespace

int run_diff_command(int argc, char** argv) {
  const Args args(argc, argv, 2, diff_options());
  if (args.flag("help")) {
    std::printf("usage: vascsim diff A.png B.png [options]\n\nCompares two images of the same size; exits 0 "
                "within tolerance, 1 otherwise, 2 on bad input.\n\n%s",
                format_options(diff_options()).c_str());
    return 0;
  }
  if (args.positional().size() != 2) throw UsageError("expected two PNG files");
  const int tolerance = static_cast<int>(args.integer("tolerance", 0, 0, 255));
  const long max_pixels = static_cast<long>(args.integer("max-pixels", 0, 0, 1LL << 40));
  const auto out = args.value("out");
  if (args.flag("force") && !out) throw UsageError("--force replaces an existing --out file, and no --out was given");
  if (out) check_replaceable_output(*out, args.flag("force"), args.positional());
  const auto different_sizes = [&](std::pair<int, int> a, std::pair<int, int> b) {
    return InputError(args.positional()[0] + " is " + std::to_string(a.first) + "x" + std::to_string(a.second) + ", " +
                      args.positional()[1] + " is " + std::to_string(b.first) + "x" + std::to_string(b.second) +
                      ": images of different sizes cannot be compared");
  };
  // From the headers first: a small file can decode to gigabytes.
  const auto size_a = io::png_dimensions(args.positional()[0]), size_b = io::png_dimensions(args.positional()[1]);
  if (size_a.first > 0 && size_b.first > 0 && size_a != size_b) throw different_sizes(size_a, size_b);
  const render::Image a = render::load_png(args.positional()[0]);
  const render::Image b = render::load_png(args.positional()[1]);
  if (a.width != b.width || a.height != b.height) throw different_sizes({a.width, a.height}, {b.width, b.height});
  render::Image heat;
  const render::DiffStats s = render::diff_images(a, b, tolerance, out ? &heat : nullptr);
  if (out) render::write_image_png(*out, heat);
  const bool pass = s.pixels_over <= max_pixels;
  // Whole levels for 8-bit images, as always; a 16-bit image's differences have fractions.
  const bool whole = std::floor(s.max_difference) == s.max_difference;
  std::printf(whole ? "max difference  %.0f\n" : "max difference  %.4f\n", s.max_difference);
  std::printf("mean difference %.4f\npixels over %d  %ld of %ld\nPSNR            ", s.mean_difference, tolerance,
              s.pixels_over, s.pixels);
  if (std::isinf(s.psnr_db)) std::printf("inf (identical)\n");
  else std::printf("%.2f dB\n", s.psnr_db);
  std::printf("%s\n", pass ? "within tolerance" : "DIFFERENT");
  return pass ? 0 : 1;
}

}  // namespace vascsim::cli

#endif  // VASCSIM_HAVE_RENDER
