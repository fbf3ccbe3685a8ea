#pragma once

// Every joint kind's state, one header each; a joint holds one of them.

#include <variant>

#include "distance_joint.hpp"
#include "gear_joint.hpp"
#include "motor_joint.hpp"
#include "prismatic_joint.hpp"
#include "pulley_joint.hpp"
#include "revolute_joint.hpp"
#include "weld_joint.hpp"
#include "wheel_joint.hpp"

namespace mink::detail {

// In JointType's order, as JointDef's alternatives.
using JointKind = std::variant<RevoluteJoint, PrismaticJoint, DistanceJoint, WeldJoint, WheelJoint,
                               MotorJoint, GearJoint, PulleyJoint>;

}  // namespace mink::detail
