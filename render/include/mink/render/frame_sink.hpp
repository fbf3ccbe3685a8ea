#pragma once

#include <filesystem>
#include <memory>

#include "mink/render/image.hpp"
#include "mink/render/video_writer.hpp"

namespace mink {

/// @brief Where a headless run's frames go: a video file (by its extension: .mp4, .mkv, .mov,
/// .webm, .avi) through ffmpeg, or else a directory of numbered PNGs (frame_00000.png, ...).
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// @brief Appends one frame.
  /// @throws like write_png or VideoWriter::write_frame.
  virtual void write(const Image& frame) = 0;
  /// @brief Finishes the output.
  /// @throws OutputError when that fails.
  virtual void close() = 0;
  /// @brief Frames written so far.
  virtual int frames_written() const = 0;
};

/// @brief Opens the sink `path` names for frames of width x height.
/// @param path a video file (by extension) or a directory for PNGs
/// @param width, height frame size in pixels
/// @param video encoder settings, used only when `path` names a video file
/// @throws OutputError when the directory cannot be made or ffmpeg cannot start
/// @throws InvalidArgumentError for a bad size
std::unique_ptr<FrameSink> open_frame_sink(const std::filesystem::path& path, int width, int height,
                                           VideoOptions video = {});

/// @brief True when `path` names a video file rather than a directory of PNGs.
bool is_video_path(const std::filesystem::path& path);

}  // namespace mink
