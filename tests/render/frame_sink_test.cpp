#include "mink/render/frame_sink.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "mink/error.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/render_error.hpp"
#include "render_test_support.hpp"

namespace {

using mink_test::temp_path;

mink::Image shade(int width, int height, std::uint8_t value) {
  mink::Image image(width, height, 3);
  std::fill(image.pixels.begin(), image.pixels.end(), value);
  return image;
}

TEST(FrameSink, TellsVideosFromDirectoriesByExtension) {
  EXPECT_TRUE(mink::is_video_path("run.mp4"));
  EXPECT_TRUE(mink::is_video_path("out/Run.MKV"));
  EXPECT_FALSE(mink::is_video_path("frames"));
  EXPECT_FALSE(mink::is_video_path("frames.d"));
}

TEST(FrameSink, WritesNumberedPngsInOrder) {
  const auto dir = temp_path("mink_frames_sequence");
  std::filesystem::remove_all(dir);
  auto sink = mink::open_frame_sink(dir, 8, 6);
  for (std::uint8_t i = 0; i < 3; ++i) sink->write(shade(8, 6, static_cast<std::uint8_t>(40 * i)));
  sink->close();
  EXPECT_EQ(sink->frames_written(), 3);
  EXPECT_EQ(mink::read_png(dir / "frame_00000.png").at(0, 0)[0], 0);
  EXPECT_EQ(mink::read_png(dir / "frame_00002.png").at(7, 5)[0], 80);
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_00003.png"));
  EXPECT_THROW(sink->write(shade(6, 8, 0)), mink::InvalidArgumentError);
  std::filesystem::remove_all(dir);
}

TEST(FrameSink, WritesVideosThroughFfmpeg) {
  const auto path = temp_path("mink_sink.mp4");
  mink::VideoOptions options;
  options.codec = "mpeg4";
  auto sink = mink::open_frame_sink(path, 16, 16, options);
  for (int i = 0; i < 4; ++i) sink->write(shade(16, 16, static_cast<std::uint8_t>(60 * i)));
  sink->close();
  EXPECT_EQ(sink->frames_written(), 4);
  EXPECT_GT(std::filesystem::file_size(path), 0u);
  std::filesystem::remove(path);
}

TEST(FrameSink, ReportsADirectoryItCannotMake) {
  const auto file = temp_path("mink_sink_blocker");
  { std::ofstream(file) << "a file, not a directory"; }
  EXPECT_THROW(mink::open_frame_sink(file / "frames", 8, 8), mink::OutputError);
  std::filesystem::remove(file);
}

}  // namespace
