# The optional parts of Minkowski. Each defaults ON and, when its package is missing, stops
# the configure step naming the Debian package to install (or the option to turn off), rather
# than failing later in a compiler or linker message.

option(MINK_WITH_RENDER "Build the OpenGL renderer (PNG, MP4, offscreen) and the mink command" ON)
option(MINK_WITH_SDL2 "Build the SDL2 window of the renderer (mink::render_window)" ON)
option(MINK_WITH_BOX2D "Build the Box2D cross-checks, comparisons and benchmarks" ON)

# Stops configuring: `part` needs `what`, which Debian ships in `debian_package`.
function(mink_missing_dependency part what debian_package option)
  message(FATAL_ERROR
    "${part} needs ${what}, which was not found.\n"
    "  Install it:  sudo apt-get install ${debian_package}   (or: scripts/install-deps.sh build)\n"
    "  or configure without it:  -D${option}=OFF")
endfunction()

if(MINK_WITH_RENDER)
  include(CheckIncludeFileCXX)
  # GL, OSMesa and EGL are opened at run time; only their headers are needed to build.
  foreach(header_and_package IN ITEMS "GL/glcorearb.h|libgl-dev" "GL/osmesa.h|libosmesa6-dev"
                                      "EGL/egl.h|libegl-dev")
    string(REPLACE "|" ";" header_and_package "${header_and_package}")
    list(GET header_and_package 0 header)
    list(GET header_and_package 1 package)
    string(MAKE_C_IDENTIFIER "MINK_HAVE_${header}" have_header)
    check_include_file_cxx(${header} ${have_header})
    if(NOT ${have_header})
      mink_missing_dependency("MINK_WITH_RENDER" "the header <${header}>" ${package}
                              MINK_WITH_RENDER)
    endif()
  endforeach()
  find_package(PNG QUIET)
  if(NOT PNG_FOUND)
    mink_missing_dependency("MINK_WITH_RENDER" "libpng" libpng-dev MINK_WITH_RENDER)
  endif()
  # The mink command (demos/) renders its scenes, so it comes with the renderer.
  find_package(CLI11 QUIET)
  if(NOT CLI11_FOUND)
    mink_missing_dependency("The mink command (MINK_WITH_RENDER)" "CLI11" libcli11-dev
                            MINK_WITH_RENDER)
  endif()
  find_package(nlohmann_json QUIET)
  if(NOT nlohmann_json_FOUND)
    mink_missing_dependency("The mink command (MINK_WITH_RENDER)" "nlohmann_json"
                            nlohmann-json3-dev MINK_WITH_RENDER)
  endif()
else()
  if(MINK_BUILD_TESTS)
    message(FATAL_ERROR
      "MINK_BUILD_TESTS needs MINK_WITH_RENDER: the test suite also covers the mink command "
      "and the renderer. Configure with -DMINK_BUILD_TESTS=OFF to build the physics libraries "
      "alone.")
  endif()
  message(STATUS "MINK_WITH_RENDER is OFF: building the physics libraries only (no renderer, "
                 "no mink command)")
endif()

# The window is part of the renderer: without the renderer there is no window to build.
if(MINK_WITH_SDL2 AND NOT MINK_WITH_RENDER)
  message(STATUS "MINK_WITH_SDL2 has no effect with MINK_WITH_RENDER OFF")
  set(MINK_WITH_SDL2 OFF)
endif()
if(MINK_WITH_SDL2)
  find_package(SDL2 QUIET)
  if(NOT SDL2_FOUND)
    mink_missing_dependency("MINK_WITH_SDL2" "SDL2" libsdl2-dev MINK_WITH_SDL2)
  endif()
endif()

# Box2D 2.4.1 is the reference the tests cross-check against and the benchmarks race; the
# library itself never links it.
if(MINK_WITH_BOX2D)
  find_package(box2d 2.4 QUIET)
  if(NOT box2d_FOUND)
    mink_missing_dependency("MINK_WITH_BOX2D" "Box2D 2.4" libbox2d-dev MINK_WITH_BOX2D)
  endif()
endif()

if(MINK_BUILD_BENCH AND NOT MINK_WITH_RENDER)
  message(FATAL_ERROR "MINK_BUILD_BENCH needs MINK_WITH_RENDER: the benchmarks include the "
                      "renderer's. Configure with -DMINK_BUILD_BENCH=OFF or -DMINK_WITH_RENDER=ON.")
endif()

# The Python module `minkowski` (python/): pybind11 and numpy, built for the Python 3 that
# Python3_EXECUTABLE names (the Makefile passes Debian's /usr/bin/python3). Not in sanitizer
# builds: an instrumented extension cannot be loaded into an uninstrumented interpreter.
option(MINK_WITH_PYTHON "Build the Python module minkowski (pybind11, numpy)" ON)
if(MINK_WITH_PYTHON AND (MINK_SANITIZE OR MINK_TSAN OR MINK_FUZZ))
  message(STATUS "MINK_WITH_PYTHON is off in sanitizer builds (the interpreter is not "
                 "instrumented)")
  set(MINK_WITH_PYTHON OFF)
endif()
if(MINK_WITH_PYTHON AND NOT MINK_WITH_RENDER)
  message(STATUS "MINK_WITH_PYTHON needs MINK_WITH_RENDER (frames as arrays): not built")
  set(MINK_WITH_PYTHON OFF)
endif()
if(MINK_WITH_PYTHON)
  find_package(Python3 3.9 QUIET COMPONENTS Interpreter Development.Module)
  if(NOT Python3_FOUND)
    mink_missing_dependency("MINK_WITH_PYTHON" "Python 3 and its headers" python3-dev
                            MINK_WITH_PYTHON)
  endif()
  find_package(pybind11 2.6 CONFIG QUIET)
  if(NOT pybind11_FOUND)
    mink_missing_dependency("MINK_WITH_PYTHON" "pybind11" pybind11-dev MINK_WITH_PYTHON)
  endif()
  execute_process(COMMAND ${Python3_EXECUTABLE} -c "import numpy"
                  RESULT_VARIABLE mink_numpy_missing OUTPUT_QUIET ERROR_QUIET)
  if(mink_numpy_missing)
    # One argument: CMake passes two adjacent quoted strings as two arguments.
    mink_missing_dependency(
      "MINK_WITH_PYTHON"
      "numpy for ${Python3_EXECUTABLE} (another interpreter: -DPython3_EXECUTABLE=PATH)"
      python3-numpy MINK_WITH_PYTHON)
  endif()
  # The module links the static libraries into a shared object: their code must be
  # position-independent. Nothing interposes their symbols, so calls between them may still
  # be inlined as in an executable.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  target_compile_options(mink_build_flags INTERFACE -fno-semantic-interposition)
endif()
