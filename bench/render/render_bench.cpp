// Frame time at 1280 x 720: draw + readback on each headless backend, the CPU side alone, and
// MP4 encoding per frame with each encoder. Cases are named case/size/implementation so
// bench/run_render.sh can write them as CSV rows.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench_scene.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/renderer.hpp"
#include "mink/render/video_writer.hpp"

namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr mink::Color kBackground{0.93f, 0.94f, 0.96f, 1};

struct Frame {
  std::unique_ptr<mink::GlContext> context;
  std::unique_ptr<mink::Renderer> renderer;
  mink::bench::BenchScene scene = mink::bench::bench_scene();

  // Shapes only unless asked: the frame a person watches; contact points are a debug layer.
  explicit Frame(mink::GlBackend backend, std::uint32_t layers = mink::draw_shapes)
      : context(mink::make_offscreen_context(backend, kWidth, kHeight)),
        renderer(std::make_unique<mink::Renderer>(*context)) {
    renderer->camera().fit(scene.lower, scene.upper, 16);
    renderer->layers = layers;
  }
  ~Frame() { renderer.reset(); }

  void draw() {
    renderer->begin_frame(kBackground);
    scene.draw(*renderer);
    renderer->draw_overlay("bodies " + std::to_string(scene.bodies));
    renderer->end_frame();
  }
};

void draw_readback(benchmark::State& state, mink::GlBackend backend, std::uint32_t layers) {
  Frame frame(backend, layers);
  mink::Image pixels;
  for (auto _ : state) {
    frame.draw();
    frame.renderer->read_pixels_into(pixels, 4);
    benchmark::DoNotOptimize(pixels.pixels.data());
  }
  state.counters["triangles"] = static_cast<double>(frame.renderer->triangle_count());
}

// The readback alone, of a frame drawn once.
void readback_only(benchmark::State& state, mink::GlBackend backend) {
  Frame frame(backend);
  frame.draw();
  mink::Image pixels;
  for (auto _ : state) {
    frame.renderer->read_pixels_into(pixels, 4);
    benchmark::DoNotOptimize(pixels.pixels.data());
  }
}

// Turning draw calls into triangles, without GL: the CPU share of a frame.
void record_only(benchmark::State& state) {
  Frame frame(mink::GlBackend::osmesa);
  for (auto _ : state) {
    frame.renderer->begin_frame(kBackground);
    frame.scene.draw(*frame.renderer);
    benchmark::DoNotOptimize(frame.renderer->triangle_count());
  }
}

// Per-frame cost of a 30-frame clip through ffmpeg, start and finish included.
void encode(benchmark::State& state, const std::string& codec) {
  constexpr int kFrames = 30;
  Frame frame(mink::GlBackend::osmesa);
  std::vector<mink::Image> frames(kFrames);
  for (int i = 0; i < kFrames; ++i) {
    // A camera sweep so consecutive frames differ as a simulation's do.
    frame.renderer->camera().follow(
        (frame.scene.lower + frame.scene.upper) / 2 + mink::Vec2(i * 0.4, 0),
        kHeight / (frame.scene.upper.y() - frame.scene.lower.y()));
    frame.draw();
    frames[static_cast<std::size_t>(i)] = frame.renderer->read_pixels(3);
  }
  const auto path = std::filesystem::temp_directory_path() / ("mink_bench_" + codec + ".mp4");
  mink::VideoOptions options;
  options.codec = codec;
  options.fps = 60;
  for (auto _ : state) {
    const auto started = std::chrono::steady_clock::now();
    mink::VideoWriter video(path, kWidth, kHeight, options);
    for (const mink::Image& image : frames) video.write_frame(image);
    video.close();
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - started;
    state.SetIterationTime(seconds.count() / kFrames);
  }
  std::filesystem::remove(path);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string size = std::to_string(mink::bench::bench_scene().bodies);
  benchmark::RegisterBenchmark(("draw_readback/" + size + "/osmesa").c_str(), draw_readback,
                               mink::GlBackend::osmesa, mink::draw_shapes)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("draw_readback/" + size + "/egl").c_str(), draw_readback,
                               mink::GlBackend::egl, mink::draw_shapes)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("draw_readback_contacts/" + size + "/osmesa").c_str(),
                               draw_readback, mink::GlBackend::osmesa,
                               mink::draw_shapes | mink::draw_contact_points)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("readback_only/" + size + "/osmesa").c_str(), readback_only,
                               mink::GlBackend::osmesa)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("record_triangles/" + size + "/cpu").c_str(), record_only)
      ->Unit(benchmark::kMillisecond);
  for (const char* codec : {"libx264", "mpeg4"}) {
    benchmark::RegisterBenchmark(("encode_frame/" + size + "/" + codec).c_str(), encode,
                                 std::string(codec))
        ->UseManualTime()
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
