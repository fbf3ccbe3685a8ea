#pragma once

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mink/engine/scene.hpp"
#include "mink/engine/scene_schedule.hpp"
#include "mink/engine/world.hpp"
#include "mink/render/renderer.hpp"
#include "recording.hpp"

namespace mink::cli {

// The interactive sandbox, apart from any window: a world built from a scene, the
// person's input (keys by name, mouse at pixels) and the frame drawn into a Renderer. The
// window loop of `mink sandbox` feeds it SDL events; tests feed it directly.
//
// Keys: space pauses, s single-steps while paused, r resets, n switches to the next scene,
// 1-9 toggle the debug layers (shapes, AABBs, contact points, contact normals, broadphase
// pairs, velocities, sleep state, centres of mass, joints), j toggles joint mode, Escape or q
// quits. The left mouse button on a dynamic body drags it with a motor joint (the grabbed
// point follows the cursor); on empty space it drops a random hull there. In joint mode a
// first click picks body A (empty space: the static world), a second click picks body B and
// pins the two with a revolute joint at that second click point. b steps back in time: the
// world (and the scene's schedule) as it was at the last kept moment, one kept every half
// second for the last ten seconds; pressed again, further back.
//
// A reset rolls the world back to the scene as built (World::restore), so a recording
// (record_to) goes on through resets; a switch to another scene ends it, as a recording holds
// one world.
class Sandbox {
 public:
  // `scene` is a built-in's name or a scene file, as for `mink run`; throws
  // InvalidArgumentError naming an unknown scene or a bad file.
  Sandbox(Renderer& renderer, const std::string& scene);
  // The scene already resolved (so a bad one fails before any window opens); `name` is shown.
  Sandbox(Renderer& renderer, std::string name, SceneDef scene);
  ~Sandbox();
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  // Records the run from now on (mink replay's format): the world's state now, then every
  // call the sandbox, the scene's schedule and the person's input make and every step's state
  // hash. finish_recording() writes it to `file`, as does a switch to another scene.
  void record_to(std::filesystem::path file);
  // Writes the recording being made to its file and ends it; returns its steps, or nothing
  // when none was being made. Throws OutputError when the file cannot be written.
  std::optional<std::size_t> finish_recording();
  bool recording() const { return recorder_ != nullptr; }

  void key(std::string_view name);
  void mouse_down(const Vec2& pixel);
  void mouse_move(const Vec2& pixel);
  void mouse_up(const Vec2& pixel);

  // Advances the world one frame (1/60 s) unless paused, then draws the frame.
  void frame();

  bool quit_requested() const { return quit_; }
  bool paused() const { return paused_; }
  const std::string& scene() const { return scene_; }
  const World& world() const { return run_.world(); }
  std::uint32_t layers() const { return renderer_.layers; }
  // The body being dragged, if any, and the motor joint that drags it.
  std::optional<BodyId> dragged() const;
  std::optional<JointId> drag_joint() const;
  bool joint_mode() const { return joint_mode_; }
  // Body A of the revolute joint being made: picked by joint mode's first click.
  std::optional<BodyId> joint_first() const { return joint_first_; }

  static constexpr Color background{0.12f, 0.12f, 0.14f, 1};
  static constexpr std::string_view help =
      "drag: move body  click: drop hull  j: joint mode (click A, click B)  space: pause  "
      "s: step  b: step back  r: reset  n: next scene  1-9: layers  q: quit";

 private:
  void reset();
  void load_scene();
  void start_afresh();
  void fit_camera();
  void step();
  void drop_hull(const Vec2& world_point);
  void step_back();
  void grab(BodyId body);
  void release();
  void pick_joint_body(const Vec2& world_point);
  BodyId world_anchor();

  Renderer& renderer_;
  std::string scene_;
  SceneDef scene_def_;               // what reset rebuilds, so a scene file is read once
  SceneRun run_;                     // the world, stepped with the scene's schedule
  std::vector<std::uint8_t> start_;  // the run's snapshot as built: what a reset restores
  std::unique_ptr<RunRecorder> recorder_;
  std::filesystem::path record_file_;
  bool paused_ = false;
  bool step_once_ = false;
  bool quit_ = false;
  std::uint64_t drops_ = 0;  // seeds the dropped hulls' shapes, so runs repeat exactly
  // A static body without shapes at the origin: body A of the drag's motor joint and of
  // joints pinned to empty space. Made when first needed; a reset drops it with the world.
  std::optional<BodyId> world_anchor_;
  struct Drag {
    BodyId body;
    JointId joint;    // motor joint from world_anchor_ to body
    Vec2 grab_local;  // the grabbed point in the body's frame
    Real angle;       // the body's angle when grabbed, held while dragged
  };
  std::optional<Drag> drag_;
  // Run snapshots to step back to (SceneRun::snapshot), oldest first, with their steps.
  struct Kept {
    std::uint64_t step;
    std::vector<std::uint8_t> snapshot;
    std::optional<JointId> drag_joint;  // the drag's motor joint, if one was under way
  };
  std::deque<Kept> history_;
  static constexpr std::uint64_t kKeepEvery = 30;  // steps: half a second
  static constexpr std::size_t kKeptCount = 20;
  bool joint_mode_ = false;
  std::optional<BodyId> joint_first_;
  std::string joint_message_;  // what joint mode's last click did, shown in the overlay
  Vec2 cursor_{0, 0};          // world
  // The help text wrapped for help_columns_ characters, redone only when the width changes.
  std::size_t help_columns_ = 0;
  std::string wrapped_help_;
};

}  // namespace mink::cli
