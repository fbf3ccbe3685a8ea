// Frames as arrays: a world drawn headless (OSMesa or EGL, as `mink run` draws it) into an
// (H, W, 3) uint8 array, and PNG and MP4 files.
#include <pybind11/stl/filesystem.h>

#include <array>
#include <filesystem>
#include <optional>

#include "bindings.hpp"
#include "mink/render/gl_context.hpp"
#include "mink/render/png_file.hpp"
#include "mink/render/renderer.hpp"
#include "mink/render/video_writer.hpp"
#include "mink/render/world_view.hpp"

namespace mink::python {

namespace {

using Pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

constexpr std::array<std::pair<const char*, DrawLayer>, 9> kLayers = {{
    {"shapes", draw_shapes},
    {"aabbs", draw_aabbs},
    {"contact_points", draw_contact_points},
    {"contact_normals", draw_contact_normals},
    {"broadphase_pairs", draw_broadphase_pairs},
    {"velocities", draw_velocities},
    {"sleep_state", draw_sleep_state},
    {"centers_of_mass", draw_centers_of_mass},
    {"joints", draw_joints},
}};

std::uint32_t layer_flags(const std::optional<std::vector<std::string>>& names) {
  if (!names) return kRunFrameLayers;
  std::uint32_t flags = 0;
  for (const std::string& name : *names) {
    bool known = false;
    std::string list;
    for (const auto& [layer_name, flag] : kLayers) {
      if (name == layer_name) {
        flags |= flag;
        known = true;
      }
      list += (list.empty() ? "'" : ", '") + std::string(layer_name) + "'";
    }
    if (!known) throw InvalidArgumentError("layer '" + name + "' is not one of " + list);
  }
  return flags;
}

py::array_t<std::uint8_t> to_array(const Image& image) {
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(image.height),
                                 static_cast<py::ssize_t>(image.width),
                                 static_cast<py::ssize_t>(image.channels)});
  std::copy(image.pixels.begin(), image.pixels.end(), out.mutable_data());
  return out;
}

Image to_image(const py::object& pixels, const char* function) {
  const Pixels array = Pixels::ensure(pixels);
  if (!array || array.ndim() != 3 || (array.shape(2) != 3 && array.shape(2) != 4)) {
    throw InvalidArgumentError(std::string(function) +
                               ": expected an (H, W, 3) or (H, W, 4) uint8 array");
  }
  Image image(static_cast<int>(array.shape(1)), static_cast<int>(array.shape(0)),
              static_cast<int>(array.shape(2)));
  std::copy(array.data(), array.data() + array.size(), image.pixels.begin());
  return image;
}

/// A headless GL context and the renderer on it, with a camera that fits the first world it
/// draws unless told otherwise.
class FrameRenderer {
 public:
  FrameRenderer(int width, int height, const std::string& backend, int samples)
      : context_(make_offscreen_context(parse_gl_backend(backend), width, height)),
        renderer_(std::make_unique<Renderer>(*context_, options(samples))) {}

  static RendererOptions options(int samples) {
    RendererOptions out;
    out.samples = samples;
    return out;
  }

  py::array_t<std::uint8_t> render(WorldHandle& handle, bool fit, const std::string& overlay,
                                   const std::optional<std::vector<std::string>>& layers) {
    const World& world = handle.world();
    const std::uint32_t flags = layer_flags(layers);
    context_->make_current();
    if (fit || !camera_set_) {
      Vec2 lower;
      Vec2 upper;
      world_bounds(world, lower, upper);
      renderer_->camera().fit(lower, upper, 24);
      camera_set_ = true;
    }
    draw_world_frame(*renderer_, world, overlay, flags);
    renderer_->read_pixels_into(image_, 3);
    return to_array(image_);
  }

  void fit(const Vec2& lower, const Vec2& upper, Real margin) {
    renderer_->camera().fit(lower, upper, margin);
    camera_set_ = true;
  }
  void follow(const Vec2& point, Real pixels_per_unit) {
    renderer_->camera().follow(point, pixels_per_unit);
    camera_set_ = true;
  }
  const Camera& camera() const { return renderer_->camera(); }
  int width() const { return context_->width(); }
  int height() const { return context_->height(); }
  std::string backend() const { return context_->name(); }

 private:
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<Renderer> renderer_;
  Image image_;
  bool camera_set_ = false;
};

/// An MP4 (or any container ffmpeg picks from the name) fed with frame arrays.
class FrameVideo {
 public:
  FrameVideo(const std::filesystem::path& path, int width, int height, int fps,
             const std::string& codec)
      : writer_(path, width, height, options(fps, codec)) {}
  static VideoOptions options(int fps, const std::string& codec) {
    VideoOptions out;
    out.fps = fps;
    out.codec = codec;
    return out;
  }
  void write(const py::object& frame) { writer_.write_frame(to_image(frame, "VideoWriter.write")); }
  void close() {
    if (!closed_) {
      closed_ = true;
      writer_.close();
    }
  }
  int frames() const { return writer_.frames_written(); }
  std::string codec() const { return writer_.codec(); }

 private:
  VideoWriter writer_;
  bool closed_ = false;
};

}  // namespace

void bind_frames(py::module_& m) {
  py::class_<FrameRenderer>(m, "Renderer", R"(Draws worlds headless into (H, W, 3) uint8 arrays.

Renderer(width=640, height=480, backend='osmesa', samples=0): a GL 3.3 context of OSMesa or
EGL (surfaceless), as `mink run --gl` makes; samples > 1 smooths edges. The camera fits the
first world drawn (World bounds, spinning kinematic bodies' sweep included) unless fit() or
follow() set it.)")
      .def(py::init<int, int, const std::string&, int>(), py::arg("width") = 640,
           py::arg("height") = 480, py::arg("backend") = "osmesa", py::arg("samples") = 0)
      .def("render", &FrameRenderer::render, py::arg("world"), py::arg("fit") = false,
           py::arg("overlay") = "", py::arg("layers") = py::none(),
           "One frame of `world` as an (H, W, 3) uint8 array, rows top to bottom. fit=True "
           "refits the camera to the world; overlay is text at the top-left corner; layers "
           "names what to draw ('shapes', 'aabbs', 'contact_points', 'contact_normals', "
           "'broadphase_pairs', 'velocities', 'sleep_state', 'centers_of_mass', 'joints'; "
           "default: shapes, contact points, sleep state).")
      .def("fit", &FrameRenderer::fit, py::arg("lower"), py::arg("upper"), py::arg("margin") = 16.0,
           "Shows the world box [lower, upper] whole and centred.")
      .def("follow", &FrameRenderer::follow, py::arg("point"), py::arg("pixels_per_unit"),
           "Centres the world point at that zoom.")
      .def_property_readonly(
          "center", [](const FrameRenderer& r) { return r.camera().center(); },
          "The world point at the frame's centre.")
      .def_property_readonly(
          "pixels_per_unit", [](const FrameRenderer& r) { return r.camera().pixels_per_unit(); },
          "Zoom.")
      .def(
          "world_to_pixel",
          [](const FrameRenderer& r, const Vec2& point) {
            return r.camera().world_to_pixel(point);
          },
          py::arg("point"), "A world point's pixel coordinates (x right, y down).")
      .def_property_readonly("width", &FrameRenderer::width)
      .def_property_readonly("height", &FrameRenderer::height)
      .def_property_readonly("backend", &FrameRenderer::backend, "'osmesa' or 'egl'.");

  py::class_<FrameVideo>(m, "VideoWriter", R"(An MP4 made by ffmpeg from frame arrays.

VideoWriter(path, width, height, fps=60, codec=''): sizes even; codec empty picks libx264 when
this ffmpeg has it, else mpeg4. Use it as a context manager, or call close().)")
      .def(py::init<const std::filesystem::path&, int, int, int, const std::string&>(),
           py::arg("path"), py::arg("width"), py::arg("height"), py::arg("fps") = 60,
           py::arg("codec") = "")
      .def("write", &FrameVideo::write, py::arg("frame"),
           "Appends an (H, W, 3) or (H, W, 4) uint8 frame of the writer's size.")
      .def("close", &FrameVideo::close, "Waits for ffmpeg to finish the file.")
      .def_property_readonly("frames", &FrameVideo::frames, "Frames written so far.")
      .def_property_readonly("codec", &FrameVideo::codec, "The encoder in use.")
      .def(
          "__enter__", [](FrameVideo& v) -> FrameVideo& { return v; },
          py::return_value_policy::reference)
      .def("__exit__", [](FrameVideo& v, const py::args&) { v.close(); });

  m.def(
       "save_png",
       [](const std::filesystem::path& path, const py::object& image) {
         write_png(path, to_image(image, "save_png"));
       },
       py::arg("path"), py::arg("image"), "Writes an (H, W, 3) or (H, W, 4) uint8 array as a PNG.")
      .def(
          "read_png", [](const std::filesystem::path& path) { return to_array(read_png(path)); },
          py::arg("path"), "A PNG as an (H, W, 4) uint8 array.");
}

}  // namespace mink::python
