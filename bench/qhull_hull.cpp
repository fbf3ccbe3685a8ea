#include "library_hulls.hpp"

#include <stdexcept>
#include <string>

#include <libqhull_r/libqhull_r.h>

namespace mink::bench {

struct QhullHullBuilder::State {
  std::vector<coordT> coordinates;  // x0, y0, x1, y1, ...
  std::vector<Vec2> hull;
  qhT qhull;  // large, so kept here rather than on the stack
};

QhullHullBuilder::QhullHullBuilder(std::span<const Vec2> points)
    : state_(std::make_unique<State>()) {
  state_->coordinates.reserve(2 * points.size());
  for (const Vec2& p : points) {
    state_->coordinates.push_back(p.x());
    state_->coordinates.push_back(p.y());
  }
  state_->hull.reserve(points.size());
}

QhullHullBuilder::~QhullHullBuilder() = default;
QhullHullBuilder::QhullHullBuilder(QhullHullBuilder&&) noexcept = default;
QhullHullBuilder& QhullHullBuilder::operator=(QhullHullBuilder&&) noexcept = default;

std::size_t QhullHullBuilder::build() {
  // The name `qh` is required: Qhull's iteration macros refer to it.
  qhT* qh = &state_->qhull;
  qh_zero(qh, nullptr);  // a fresh state per build, as if each were the first call
  char command[] = "qhull";
  const int point_count = static_cast<int>(state_->coordinates.size() / 2);
  // No output file: nothing is printed. A null error file means stderr, so failures show.
  const int exit_code = qh_new_qhull(qh, 2, point_count, state_->coordinates.data(), False, command,
                                     nullptr, nullptr);
  state_->hull.clear();
  if (exit_code == 0) {
    vertexT* vertex = nullptr;
    FORALLvertices {
      if (!vertex->deleted) state_->hull.emplace_back(vertex->point[0], vertex->point[1]);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int unfreed_long = 0;
  int unfreed_total = 0;
  qh_memfreeshort(qh, &unfreed_long, &unfreed_total);
  if (exit_code != 0) {
    throw std::runtime_error("qh_new_qhull failed with exit code " + std::to_string(exit_code));
  }
  return state_->hull.size();
}

std::vector<Vec2> QhullHullBuilder::vertices() const {
  return state_->hull;
}

}  // namespace mink::bench
