#pragma once

#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "id_pool.hpp"
#include "joint.hpp"
#include "joint_chain_solver.hpp"
#include "joint_rows.hpp"
#include "pin_rows.hpp"
#include "revolute_rows.hpp"
#include "task_runner.hpp"

namespace mink::detail {

// The joints' part of each substep stage, run by the contact solver's substep loop before its
// contacts, in the order prepare_joints chose: colour by colour (the overflow last), the
// chains' point rows first in each solve. A colour's joints share no moving body, so the
// solver may run any range of a colour on any worker. Revolute joints outside the chains are
// solved from compact rows laid out in that order, not from their kilobyte records, kWideLanes
// at a time in SIMD lanes: those that are only a point row (pins), and the others (ragdolls'
// joints, with springs, motors and limits).
class JointStages {
 public:
  // `order`: the joints, by colour; `color_begin`: where each colour starts in it (one past the
  // overflow at the end).
  void set(IdPool<Joint>* joints, const std::vector<std::uint32_t>* order,
           const std::vector<std::uint32_t>* color_begin) {
    joints_ = joints;
    order_ = order;
    color_begin_ = color_begin;
  }
  bool empty() const { return order_ == nullptr || order_->empty(); }
  // Room for each joint of the order; each is solved from its record until gather() says
  // otherwise.
  void reset(std::size_t joint_count) {
    pins_.resize(joint_count);
    ends_.resize(joint_count);
    row_slot_.resize(joint_count);
    kind_.assign(joint_count, RowKind::record);
    wide_lane_.assign(joint_count, kNoLane);
  }
  // Takes what the step's passes read of the joint at `position` of the order, from its
  // prepared frame, while its record is in cache: its ends for the chains; a revolute joint
  // (one with a spring, motor or limit: a pin is gathered by gather_pin) is marked for a
  // revolute row. Thread safe across positions.
  void gather(std::uint32_t position, Joint& joint);
  // The same for a pin, prepared outside its record (WorldState::prepare_joint) in `frame`:
  // also the pin row it is then solved from instead of its record. Thread safe across
  // positions.
  void gather_pin(std::uint32_t position, const JointFrame& frame, const RevoluteJoint& joint);
  // Finds the chains (JointChainSolver::build), whose point rows are solved from their records
  // (a chained joint's angle rows stay a row), and gives each revolute row its place; returns
  // how many there are.
  std::size_t build_chains(bool enabled);
  // The pins build_chains() put in chains, which are solved from their records: their
  // records' frames must be prepared.
  const std::vector<std::uint32_t>& chained_pins() const { return chained_pins_; }
  // Lays out the passes over the joints, once the chains are known: colour by colour (the
  // overflow last), and within a colour (whose joints share no moving body, so their order
  // changes no bit) when `wide` the pins kWideLanes at a time first, then the revolute rows
  // with a point row and those without, then the other joints one at a time. Fills the wide
  // rows, in parallel over `tasks`.
  void lay_out(bool wide, TaskRunner& tasks);
  // Where each colour's units begin (one past the overflow at the end): a unit is kWideLanes
  // pins, kWideLanes revolute rows or one joint, and the passes below run units [begin, end).
  const std::vector<std::uint32_t>& unit_begin() const { return unit_begin_; }
  // The place in the order of revolute row `slot`.
  std::uint32_t revolute_row_position(std::size_t slot) const { return revolute_positions_[slot]; }
  // Copies the prepared frame and state of the joint at `position` (a revolute row's) into its
  // row. Thread safe across positions.
  void fill_revolute_row(std::uint32_t position, const Joint& joint);
  // Gives the joint at `position` what its row's solve changed (its impulses), once the
  // substeps are done; nothing for a joint solved from its record.
  void store_row(std::uint32_t position, Joint& joint) const;
  // Units [begin, end).
  void warm_start(SolverBody* bodies, std::uint32_t begin, std::uint32_t end);
  void solve(SolverBody* bodies, bool use_bias, std::uint32_t begin, std::uint32_t end);
  // The chains' paths [first, last) (chain_paths() in all): their point rows' warm start,
  // before the units', and their solve, before the units'.
  void warm_start_chains(SolverBody* bodies, std::uint32_t first, std::uint32_t last);
  void solve_chains(SolverBody* bodies, bool use_bias, std::uint32_t first, std::uint32_t last);
  std::uint32_t chain_paths() const { return chains_.path_count(); }

 private:
  // What a joint is solved from: its record; a pin row; a revolute row (every other revolute
  // joint outside a chain: ragdolls), all kept in solve order; a revolute row without its point
  // row (a chained joint with a spring, motor or limit); or nothing but its chain (a chained
  // pin).
  enum class RowKind : std::uint8_t { record, pin, revolute, revolute_angles, chained };
  JointChainSolver chains_;
  std::vector<PinRow> pins_;  // per position of the order: valid where a pin
  // A unit: kWidePinUnit or kWideRevoluteUnit and the index of its wide row, or the position
  // of its joint.
  static constexpr std::uint32_t kWidePinUnit = 0x80000000u, kWideRevoluteUnit = 0x40000000u;
  static constexpr std::uint32_t kUnitIndex = 0x3fffffffu;
  static constexpr std::uint32_t kNoLane = ~0u;
  std::vector<std::uint32_t> units_;
  std::vector<std::uint32_t> unit_begin_;
  std::vector<WidePinRows> wide_pins_;
  std::vector<WideRevoluteRows> wide_revolutes_;
  // Per position: its lane in the wide rows of its kind, where it has one.
  std::vector<std::uint32_t> wide_lane_;
  // Per lane of the wide rows: its joint's position (an unused lane's: the first lane's).
  std::vector<std::uint32_t> wide_pin_positions_, wide_revolute_positions_;
  std::vector<JointEnds> ends_;             // per position of the order
  std::vector<RowKind> kind_;               // per position; bytes, set from several threads
  std::vector<std::uint32_t> row_slot_;     // per position: its revolute row, where it has one
  std::vector<RevoluteRow> revolute_rows_;  // per row slot
  std::vector<std::uint32_t> revolute_positions_;  // per revolute row: its position
  std::vector<std::uint32_t> chained_pins_;
  IdPool<Joint>* joints_ = nullptr;
  const std::vector<std::uint32_t>* order_ = nullptr;
  const std::vector<std::uint32_t>* color_begin_ = nullptr;
};

}  // namespace mink::detail
