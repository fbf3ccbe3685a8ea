# `cmake --install BUILD --prefix P`: the headers, the libraries (static by default, shared
# with -DBUILD_SHARED_LIBS=ON), the mink command, the `minkowski` CMake package (targets
# mink::mink, mink::geometry, ..., mink::render, mink::render_window) and minkowski.pc.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The physics engine and the layers under it; the umbrella mink::mink is exactly these.
set(mink_physics_layers geometry broadphase narrowphase engine)
set(mink_installed_layers ${mink_physics_layers})
if(TARGET mink_render)
  list(APPEND mink_installed_layers render)
endif()

add_library(mink_mink INTERFACE)
add_library(mink::mink ALIAS mink_mink)
set_target_properties(mink_mink PROPERTIES EXPORT_NAME mink)
foreach(layer IN LISTS mink_physics_layers)
  target_link_libraries(mink_mink INTERFACE mink::${layer})
endforeach()

set(mink_installed_targets mink_mink)
foreach(layer IN LISTS mink_installed_layers)
  target_include_directories(mink_${layer} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  list(APPEND mink_installed_targets mink_${layer})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          COMPONENT development
          PATTERN "sdl_window.hpp" EXCLUDE)
endforeach()
if(TARGET mink_render_window)
  list(APPEND mink_installed_targets mink_render_window)
  install(FILES ${PROJECT_SOURCE_DIR}/render/include/mink/render/sdl_window.hpp
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mink/render COMPONENT development)
endif()
foreach(target IN LISTS mink_installed_targets)
  if(NOT target STREQUAL "mink_mink")
    string(REGEX REPLACE "^mink_" "" export_name ${target})
    # Shared layers find each other next to themselves wherever the prefix is moved.
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name}
                          VERSION ${PROJECT_VERSION}
                          SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
                          INSTALL_RPATH "$ORIGIN")
  endif()
endforeach()

# A static library's private link items stay in its link interface (as $<LINK_ONLY:...>), so
# the warning/sanitizer target goes into the export set too. Consumers receive only its link
# options through LINK_ONLY: none, or -fsanitize=... which a sanitized static library needs.
set_target_properties(mink_build_flags PROPERTIES EXPORT_NAME build_flags)
list(APPEND mink_installed_targets mink_build_flags)

install(TARGETS ${mink_installed_targets}
        EXPORT minkowskiTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
if(TARGET mink)
  set_target_properties(mink PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
  install(TARGETS mink RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
endif()

set(mink_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/minkowski)
install(EXPORT minkowskiTargets
        NAMESPACE mink::
        DESTINATION ${mink_cmake_dir}
        COMPONENT development)

# What the installed package holds, for its config file.
if(TARGET mink_render)
  set(MINK_PACKAGE_HAS_RENDER ON)
else()
  set(MINK_PACKAGE_HAS_RENDER OFF)
endif()
if(TARGET mink_render_window)
  set(MINK_PACKAGE_HAS_RENDER_WINDOW ON)
else()
  set(MINK_PACKAGE_HAS_RENDER_WINDOW OFF)
endif()
configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/minkowskiConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/minkowskiConfig.cmake
  INSTALL_DESTINATION ${mink_cmake_dir})
# 0.x releases may break the API at each minor version.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/package/minkowskiConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/minkowskiConfig.cmake
              ${PROJECT_BINARY_DIR}/package/minkowskiConfigVersion.cmake
        DESTINATION ${mink_cmake_dir}
        COMPONENT development)

# pkg-config: the physics libraries (what mink::mink holds), relocatable through ${pcfiledir}.
set(mink_pkgconfig_dir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH MINK_PC_PREFIX_FROM_PCFILEDIR /root/${mink_pkgconfig_dir} /root)
string(REGEX REPLACE "/$" "" MINK_PC_PREFIX_FROM_PCFILEDIR "${MINK_PC_PREFIX_FROM_PCFILEDIR}")
set(MINK_PC_LIBS "")
foreach(layer engine narrowphase broadphase geometry)  # users before what they use
  string(APPEND MINK_PC_LIBS " -lmink_${layer}")
endforeach()
string(APPEND MINK_PC_LIBS " -pthread")  # the engine's worker pool
if(MINK_SANITIZE AND NOT BUILD_SHARED_LIBS)
  # Sanitizer-instrumented static code needs the sanitizer runtimes in the final link.
  string(APPEND MINK_PC_LIBS " -fsanitize=address,undefined")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/minkowski.pc.in ${PROJECT_BINARY_DIR}/package/minkowski.pc
               @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/minkowski.pc
        DESTINATION ${mink_pkgconfig_dir}
        COMPONENT development)
