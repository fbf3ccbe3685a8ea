#include <memory>
#include <ostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "gjk_crosscheck.hpp"
#include "shape_crosscheck.hpp"

namespace mink::cli {

namespace {

struct CrosscheckSettings {
  std::uint64_t pairs = 1'000'000;
  std::uint64_t seed = 1;
  double band = 1e-6;
  std::uint64_t shape_pairs = 100'000;
  bool run_shapes = false;  // `crosscheck shapes` rather than `crosscheck gjk`
};

}  // namespace

Action add_crosscheck_command(CLI::App& app, Streams streams) {
  auto settings = std::make_shared<CrosscheckSettings>();
  CLI::App* command = app.add_subcommand(
      "crosscheck", "Compare Minkowski's narrowphase with Box2D 2.4.1 on random pairs.");
  command->require_subcommand(1);
  CLI::App* gjk = command->add_subcommand(
      "gjk",
      "GJK verdicts and distances against Box2D's b2Distance (radius-0 proxies, useRadii =\n"
      "false) on random hull pairs with float coordinates: 3..8 vertices, and one pair in ten\n"
      "with 16..1024 vertices through the same call. Prints every disagreement with its\n"
      "distance to touching, then a summary.\n"
      "Exit codes: 0 all verdicts agree outside the band and all distances agree to float\n"
      "precision; 1 otherwise.");
  gjk->add_option("--pairs", settings->pairs, "number of random pairs (default 1000000)");
  gjk->add_option("--seed", settings->seed, "random seed (default 1)");
  gjk->add_option("--band", settings->band,
                  "verdicts may differ within this distance of touching (default 1e-6)")
      ->check(CLI::PositiveNumber);
  CLI::App* shapes = command->add_subcommand(
      "shapes",
      "Touching verdicts of collide_shapes against Box2D's b2CollideCircles,\n"
      "b2CollidePolygonAndCircle, b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon (two-sided\n"
      "edges) on random pairs with float coordinates, the four kinds in turn. Box2D's polygons\n"
      "and edges carry a skin of b2_polygonRadius, so they are compared with our rounded\n"
      "polygons and capsules of that radius. Touching means points with a separation <= 0 on\n"
      "both sides. Prints every disagreement with its distance to touching, then a summary.\n"
      "Exit codes: 0 all verdicts agree outside the band; 1 otherwise.");
  shapes->add_option("--pairs", settings->shape_pairs, "number of random pairs (default 100000)");
  shapes->add_option("--seed", settings->seed, "random seed (default 1)");
  shapes
      ->add_option("--band", settings->band,
                   "verdicts may differ within this distance of touching (default 1e-6)")
      ->check(CLI::PositiveNumber);
  shapes->callback([settings] { settings->run_shapes = true; });
  return [settings, streams] {
    if (settings->run_shapes) {
      const ShapeCrosscheckReport report =
          run_shape_crosscheck(settings->shape_pairs, settings->seed, settings->band, streams.out);
      return report.verdict_outside_band == 0 ? kSuccess : kInternalError;
    }
    const CrosscheckReport report =
        run_gjk_crosscheck(settings->pairs, settings->seed, settings->band, streams.out);
    return report.verdict_outside_band == 0 && report.distance_differs == 0 ? kSuccess
                                                                            : kInternalError;
  };
}

}  // namespace mink::cli
