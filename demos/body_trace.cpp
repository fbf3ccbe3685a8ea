#include "body_trace.hpp"

#include <cstdio>
#include <string_view>

#include "output_files.hpp"

namespace mink::cli {

namespace {

constexpr std::string_view kWhat = "--trace file";

}  // namespace

BodyTrace::BodyTrace(const std::filesystem::path& path, std::span<const BodyId> bodies,
                     std::uint64_t every)
    : path_(path),
      out_(path, std::string(kWhat)),
      bodies_(bodies.begin(), bodies.end()),
      every_(every) {
  out_.stream() << "step,body,x,y,angle,vx,vy,w\n";
}

void BodyTrace::write_step(const World& world) {
  const std::uint64_t step = world.step_count();
  if (step % every_ != 0) return;
  char row[256];
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyId body = bodies_[i];
    if (!world.is_valid(body)) continue;  // destroyed during the run by the scene's schedule
    const Vec2 p = world.position(body);
    // The world keeps the centre of mass's velocity; the origin's differs when spinning.
    const Real w = world.angular_velocity(body);
    const Vec2 r = p - world.world_center(body);
    const Vec2 v = world.linear_velocity(body) + w * Vec2(-r.y(), r.x());
    std::snprintf(row, sizeof row, "%llu,%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  static_cast<unsigned long long>(step), i, p.x(), p.y(), world.angle(body), v.x(),
                  v.y(), w);
    out_.stream() << row;
    ++rows_;
  }
}

void BodyTrace::close() {
  out_.commit();
}

}  // namespace mink::cli
