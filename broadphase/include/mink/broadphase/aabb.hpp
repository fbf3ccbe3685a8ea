#pragma once

// Aabb lives in geometry so that the broadphase and the narrowphase share it.
#include "mink/geometry/aabb.hpp"
