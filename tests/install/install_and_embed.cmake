# cmake -DBUILD_DIR=... -DEXAMPLE_DIR=... -DWORK_DIR=... -DCXX_COMPILER=... -DPKG_CONFIG=...
#       -DSHARED=... -P install_and_embed.cmake
# Fails (FATAL_ERROR) on the first step that does not work, printing that step's output.
cmake_minimum_required(VERSION 3.25)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

# The example prints one line per dropped body; each must have fallen and come to rest on the
# ground (top face at y = 0; every body's origin lies inside its hull, so y > 0) or on another
# body (so no higher than a few hull heights).
function(check_bodies_at_rest what output)
  string(REGEX MATCHALL "body [0-9]+ start_y=[-0-9.]+ x=[-0-9.]+ y=[-0-9.]+ speed=[0-9.]+"
         lines "${output}")
  list(LENGTH lines count)
  if(NOT count EQUAL 4)
    message(FATAL_ERROR "${what}: expected 4 body lines, got ${count}:\n${output}")
  endif()
  foreach(line IN LISTS lines)
    string(REGEX MATCH "start_y=([-0-9.]+) x=[-0-9.]+ y=([-0-9.]+) speed=([0-9.]+)" _ "${line}")
    set(start_y ${CMAKE_MATCH_1})
    set(y ${CMAKE_MATCH_2})
    set(speed ${CMAKE_MATCH_3})
    # if() compares decimal numbers as doubles.
    if(NOT y GREATER 0 OR NOT y LESS 3)
      message(FATAL_ERROR "${what}: a body is not resting on the ground (${line})\n${output}")
    endif()
    if(NOT y LESS start_y)
      message(FATAL_ERROR "${what}: a body did not fall (${line})\n${output}")
    endif()
    if(NOT speed LESS 0.05)
      message(FATAL_ERROR "${what}: a body is still moving at ${speed} m/s (${line})\n${output}")
    endif()
  endforeach()
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})

run_step("Installing the build" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed IN ITEMS include/mink/engine/world.hpp include/mink/geometry/convex_hull.hpp
                           include/mink/error.hpp)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "The install has no ${installed}")
  endif()
endforeach()
file(GLOB_RECURSE config_files ${prefix}/*/minkowskiConfig.cmake
     ${prefix}/*/minkowskiConfigVersion.cmake ${prefix}/*/minkowski.pc)
list(LENGTH config_files config_count)
if(NOT config_count EQUAL 3)
  message(FATAL_ERROR "The install lacks the CMake package or minkowski.pc: ${config_files}")
endif()

# 1. Through the CMake package, exactly as examples/embed/CMakeLists.txt says.
run_step("Configuring the example" ${CMAKE_COMMAND} -S ${EXAMPLE_DIR} -B ${WORK_DIR}/cmake_build
         -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
         -DCMAKE_PREFIX_PATH=${prefix})
run_step("Building the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/cmake_build)
run_step("Running the example" ${WORK_DIR}/cmake_build/embed)
message(STATUS "find_package build:\n${step_output}")
check_bodies_at_rest("find_package build" "${step_output}")

# 2. Through pkg-config, with nothing but the compiler.
if(NOT PKG_CONFIG)
  message(FATAL_ERROR "pkg-config not found: sudo apt-get install pkg-config")
endif()
file(GLOB_RECURSE pc_file ${prefix}/*/minkowski.pc)
get_filename_component(pc_dir ${pc_file} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run_step("pkg-config" ${PKG_CONFIG} --cflags --libs minkowski)
string(STRIP "${step_output}" pc_flags)
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
run_step("Compiling the example with pkg-config flags" ${CXX_COMPILER} -std=c++20 -O2
         ${EXAMPLE_DIR}/main.cpp ${pc_flags} -o ${WORK_DIR}/embed_pkg_config)
if(SHARED)
  get_filename_component(lib_dir ${pc_dir} DIRECTORY)
  set(ENV{LD_LIBRARY_PATH} ${lib_dir})
endif()
run_step("Running the pkg-config build" ${WORK_DIR}/embed_pkg_config)
check_bodies_at_rest("pkg-config build" "${step_output}")
message(STATUS "pkg-config build:\n${step_output}")
