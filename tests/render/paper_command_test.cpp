// `mink paper` end to end: the five figures are written, at the asked size, and show what
// they are about.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_support.hpp"
#include "mink/render/png_file.hpp"
#include "render_test_support.hpp"

namespace {

using mink_test::CliResult;
using mink_test::count_pixels;
using mink_test::Rgb;
using mink_test::run_cli;

// Pixels of exactly this colour in columns [x0, x1).
int count(const mink::Image& image, Rgb rgb, int x0, int x1) {
  return count_pixels(image, rgb, {x0, 0, x1, image.height});
}

class PaperCommand : public testing::TestWithParam<std::string> {};

TEST_P(PaperCommand, WritesTheFiveFigures) {
  const auto dir = mink_test::temp_path("mink_paper_" + GetParam());
  std::filesystem::remove_all(dir);
  const CliResult result =
      run_cli({"paper", "--out", dir.string(), "--gl", GetParam(), "--size", "480x300"});
  ASSERT_EQ(result.code, 0) << result.err;
  for (const char* name : {"fig08_point_sets.png", "fig09_chan.png", "fig10_divide_conquer.png",
                           "fig12_gjk_verdict.png", "fig13_minkowski_difference.png"}) {
    const mink::Image image = mink::read_png(dir / name);
    EXPECT_EQ(image.width, 480) << name;
    EXPECT_EQ(image.height, 300) << name;
    EXPECT_NE(result.out.find(name), std::string::npos);
  }
  // Figure 8: set A's blue on the left panel only, set B's orange on the right only.
  const mink::Image fig8 = mink::read_png(dir / "fig08_point_sets.png");
  const Rgb blue = {33, 102, 204};
  const Rgb orange = {217, 102, 13};
  EXPECT_GT(count(fig8, blue, 0, 240), 100);
  EXPECT_EQ(count(fig8, blue, 240, 480), 0);
  EXPECT_GT(count(fig8, orange, 240, 480), 100);
  EXPECT_EQ(count(fig8, orange, 0, 240), 0);
  // Figure 10: the upper tangent's magenta and the lower tangent's green are there.
  const mink::Image fig10 = mink::read_png(dir / "fig10_divide_conquer.png");
  EXPECT_GT(count(fig10, {204, 26, 115}, 0, 480), 20);
  EXPECT_GT(count(fig10, {26, 153, 77}, 0, 480), 20);
  // Figure 12: both hulls in both panels; figure 13: the origin marker's red in both panels.
  const mink::Image fig12 = mink::read_png(dir / "fig12_gjk_verdict.png");
  for (const int x0 : {0, 240}) {
    EXPECT_GT(count(fig12, blue, x0, x0 + 240), 20) << x0;
    EXPECT_GT(count(fig12, orange, x0, x0 + 240), 20) << x0;
  }
  const mink::Image fig13 = mink::read_png(dir / "fig13_minkowski_difference.png");
  for (const int x0 : {0, 240}) EXPECT_GT(count(fig13, {217, 13, 26}, x0, x0 + 240), 20) << x0;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Backends, PaperCommand, testing::Values("osmesa", "egl"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(PaperCommandErrors, NameTheBadOption) {
  const auto dir = mink_test::temp_path("mink_paper_bad");
  CliResult result = run_cli({"paper", "--out", dir.string(), "--gl", "vulkan"});
  EXPECT_EQ(result.code, 2);
  EXPECT_NE(result.err.find("vulkan"), std::string::npos);
  result = run_cli({"paper", "--out", dir.string(), "--size", "big"});
  EXPECT_EQ(result.code, 2);
  EXPECT_NE(result.err.find("big"), std::string::npos);
  result = run_cli({"paper", "--out", dir.string(), "--size", "10x10"});
  EXPECT_EQ(result.code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "fig08_point_sets.png"));
}

}  // namespace
