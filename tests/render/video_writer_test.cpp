#include "mink/render/video_writer.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "mink/error.hpp"
#include "mink/render/render_error.hpp"
#include "render_test_support.hpp"

namespace {

using mink::Vec2;
using mink_test::temp_path;

mink::VideoOptions options(int fps, std::string codec, std::string ffmpeg = "ffmpeg") {
  mink::VideoOptions options;
  options.fps = fps;
  options.codec = std::move(codec);
  options.ffmpeg = std::move(ffmpeg);
  return options;
}

// ffprobe decodes every frame and counts them.
std::string probe(const std::filesystem::path& video, const std::string& entry) {
  const std::string command =
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=" +
      entry + " -of default=noprint_wrappers=1:nokey=1 '" + video.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  std::string output;
  char buffer[256];
  while (fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  pclose(pipe);
  while (!output.empty() && output.back() == '\n') output.pop_back();
  return output;
}

class VideoWriterTest : public testing::TestWithParam<std::string> {};

TEST_P(VideoWriterTest, WritesEveryRenderedFrame) {
  const auto path = temp_path("mink_frames_" + GetParam() + ".mp4");
  mink_test::Headless frame(mink::GlBackend::osmesa, 96, 64);
  mink::Renderer& r = *frame.renderer;
  r.camera().fit(Vec2(0, 0), Vec2(24, 16), 0);
  constexpr int kFrames = 17;
  {
    mink::VideoWriter video(path, 96, 64, options(30, GetParam()));
    EXPECT_EQ(video.codec(), GetParam());
    mink::Image pixels;
    for (int i = 0; i < kFrames; ++i) {
      r.begin_frame(mink::Color{0, 0, 0, 1});
      const double x = i;
      const Vec2 box[] = {{x, 4}, {x + 6, 4}, {x + 6, 10}, {x, 10}};
      r.draw_polygon(box, mink::Color{1, 0.5f, 0, 1}, mink::Color{1, 1, 1, 1});
      r.end_frame();
      r.read_pixels_into(pixels, i % 2 == 0 ? 3 : 4);  // both layouts are accepted
      video.write_frame(pixels);
    }
    EXPECT_EQ(video.frames_written(), kFrames);
    video.close();
  }
  ASSERT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(probe(path, "nb_read_frames"), std::to_string(kFrames));
  EXPECT_EQ(probe(path, "width"), "96");
  EXPECT_EQ(probe(path, "height"), "64");
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(Codecs, VideoWriterTest, testing::Values("libx264", "mpeg4"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(VideoWriter, PicksAnEncoderThisFfmpegHas) {
  EXPECT_TRUE(mink::ffmpeg_has_encoder("ffmpeg", "mpeg4"));
  EXPECT_FALSE(mink::ffmpeg_has_encoder("ffmpeg", "no-such-encoder"));
  const auto path = temp_path("mink_default_codec.mp4");
  mink::VideoWriter video(path, 16, 16);
  EXPECT_EQ(video.codec(), mink::ffmpeg_has_encoder("ffmpeg", "libx264") ? "libx264" : "mpeg4");
  video.write_frame(mink::Image(16, 16, 3));
  video.close();
  std::filesystem::remove(path);
}

TEST(VideoWriter, AMissingFfmpegIsAnOutputError) {
  try {
    mink::VideoWriter video(temp_path("mink_never.mp4"), 16, 16,
                            options(60, "mpeg4", "/nonexistent/ffmpeg"));
    FAIL() << "started a missing program";
  } catch (const mink::OutputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/ffmpeg"), std::string::npos);
  }
}

TEST(VideoWriter, FfmpegFailuresSurfaceWithItsMessage) {
  // An unknown encoder: ffmpeg exits at once; the error arrives on a write or on close.
  const auto run = [] {
    mink::VideoWriter video(temp_path("mink_bad_codec.mp4"), 16, 16,
                            options(60, "no-such-encoder"));
    const mink::Image frame(16, 16, 3);
    for (int i = 0; i < 200; ++i) video.write_frame(frame);
    video.close();
  };
  try {
    run();
    FAIL() << "an unknown encoder went unnoticed";
  } catch (const mink::OutputError& error) {
    EXPECT_NE(std::string(error.what()).find("no-such-encoder"), std::string::npos) << error.what();
  }
  // A directory that does not exist: refused before ffmpeg starts, as its file is made first.
  EXPECT_THROW(mink::VideoWriter("/nonexistent-directory/out.mp4", 16, 16, options(60, "mpeg4")),
               mink::FileWriteError);
}

TEST(VideoWriter, RejectsSizesAndFramesThatDoNotFit) {
  EXPECT_THROW(mink::VideoWriter(temp_path("x.mp4"), 15, 16), mink::InvalidArgumentError);
  EXPECT_THROW(mink::VideoWriter(temp_path("x.mp4"), 16, 16, options(0, "mpeg4")),
               mink::InvalidArgumentError);
  mink::VideoWriter video(temp_path("mink_size.mp4"), 16, 16, options(60, "mpeg4"));
  EXPECT_THROW(video.write_frame(mink::Image(16, 18, 3)), mink::InvalidArgumentError);
  video.write_frame(mink::Image(16, 16, 4));
  video.close();
  EXPECT_THROW(video.write_frame(mink::Image(16, 16, 3)), mink::OutputError);
  std::filesystem::remove(temp_path("mink_size.mp4"));
}

}  // namespace
