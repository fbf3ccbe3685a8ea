#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/png_file.hpp"
#include "output_files.hpp"
#include "paper_figures.hpp"
#include "scene_view.hpp"

namespace mink::cli {

namespace {

struct PaperOptions {
  std::string out;
  std::string gl = "osmesa";
  std::string size = "1200x700";
  PaperSettings settings;
};

int run_paper(PaperOptions options, Streams streams) {
  options.settings.backend = parse_gl_backend(options.gl);
  parse_frame_size(options.size, options.settings.width, options.settings.height,
                   {.require_even = false, .example = "1200x700"});
  const std::filesystem::path out(options.out);
  make_directories(out, "--out");
  const auto context = make_offscreen_context(options.settings.backend, options.settings.width,
                                              options.settings.height);
  RendererOptions renderer_options;
  renderer_options.samples = 4;  // smooth edges for figures
  Renderer renderer(*context, renderer_options);
  for (const PaperFigure& figure : paper_figures()) {
    renderer.begin_frame(Color{1, 1, 1, 1});
    figure.draw(renderer, options.settings);
    renderer.end_frame();
    const std::filesystem::path file = out / figure.file;
    write_png(file, renderer.read_pixels(3));
    streams.out << "wrote " << file.string() << " (" << figure.caption << ")\n";
  }
  return kSuccess;
}

}  // namespace

Action add_paper_command(CLI::App& app, Streams streams) {
  auto options = std::make_shared<PaperOptions>();
  CLI::App* command = app.add_subcommand(
      "paper",
      "Draw the paper's figures (8: point sets, 9: Chan, 10: divide and conquer, 12: GJK "
      "verdict after translate/scale, 13: Minkowski difference and final simplex) as PNG "
      "files, headless.");
  command->add_option("--out", options->out, "directory for the PNG files")->required();
  command->add_option("--gl", options->gl, "headless GL backend: osmesa (default) or egl");
  command->add_option("--size", options->size, "image size WIDTHxHEIGHT (default 1200x700)");
  command->add_option("--seed", options->settings.seed, "random seed (default 2013)");
  command->add_option("--points", options->settings.count, "points in each set (default 500)")
      ->check(CLI::Range(std::size_t{3}, std::size_t{100'000}));
  return [options, streams] { return run_paper(*options, streams); };
}

}  // namespace mink::cli
