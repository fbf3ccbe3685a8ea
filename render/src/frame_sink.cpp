#include "mink/render/frame_sink.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <string>
#include <system_error>

#include "mink/error.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/render_error.hpp"

namespace mink {

namespace {

class VideoSink final : public FrameSink {
 public:
  VideoSink(const std::filesystem::path& path, int width, int height, VideoOptions options)
      : video_(path, width, height, std::move(options)) {}
  void write(const Image& frame) override { video_.write_frame(frame); }
  void close() override { video_.close(); }
  int frames_written() const override { return video_.frames_written(); }

 private:
  VideoWriter video_;
};

class PngSequenceSink final : public FrameSink {
 public:
  PngSequenceSink(std::filesystem::path directory, int width, int height)
      : directory_(std::move(directory)), width_(width), height_(height) {
    if (width <= 0 || height <= 0) {
      throw InvalidArgumentError("frame size " + std::to_string(width) + " x " +
                                 std::to_string(height) + " is not positive");
    }
    std::error_code error;
    std::filesystem::create_directories(directory_, error);
    if (error || !std::filesystem::is_directory(directory_)) {
      throw FileWriteError("cannot make the frame directory " + directory_.string() +
                           (error ? ": " + error.message() : ""));
    }
  }
  void write(const Image& frame) override {
    if (frame.width != width_ || frame.height != height_) {
      throw InvalidArgumentError("frame of " + std::to_string(frame.width) + " x " +
                                 std::to_string(frame.height) + " for a sequence of " +
                                 std::to_string(width_) + " x " + std::to_string(height_));
    }
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frames_);
    write_png(directory_ / name, frame);
    ++frames_;
  }
  void close() override {}
  int frames_written() const override { return frames_; }

 private:
  std::filesystem::path directory_;
  int width_;
  int height_;
  int frames_ = 0;
};

}  // namespace

bool is_video_path(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  constexpr std::array<const char*, 5> kVideo = {".mp4", ".mkv", ".mov", ".webm", ".avi"};
  return std::find(kVideo.begin(), kVideo.end(), extension) != kVideo.end();
}

std::unique_ptr<FrameSink> open_frame_sink(const std::filesystem::path& path, int width, int height,
                                           VideoOptions video) {
  if (is_video_path(path))
    return std::make_unique<VideoSink>(path, width, height, std::move(video));
  return std::make_unique<PngSequenceSink>(path, width, height);
}

}  // namespace mink
