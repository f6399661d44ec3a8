# MeshLab 2020.09 host (Debian 12's meshlab package, float precision).
# Defines the INTERFACE target meshlab_host: the 2020.09 source headers and vcglib (from
# scripts/setup, in .deps/meshlab-2020.09), the definitions libmeshlab-common was built with,
# Qt5, GLEW, and Debian's own libmeshlab-common.so, so the plugin is ABI-compatible with
# /usr/bin/meshlab and /usr/bin/meshlabserver.
set(MESHLAB2020_SOURCE_DIR "${CMAKE_SOURCE_DIR}/.deps/meshlab-2020.09" CACHE PATH
    "MeshLab 2020.09 source tree (headers and vcglib)")
set(MESHLAB2020_LIB_DIR "/usr/lib/x86_64-linux-gnu/meshlab" CACHE PATH
    "Folder holding Debian's libmeshlab-common.so")
# Where `cmake --install` puts the plugin: the folder Debian's meshlab loads plugins from.
set(SLICEREUSE_PLUGIN_INSTALL_DIR "${MESHLAB2020_LIB_DIR}/plugins" CACHE PATH
    "Install folder for the MeshLab plugin")

if(NOT EXISTS "${MESHLAB2020_SOURCE_DIR}/src/common/interfaces.h")
  message(FATAL_ERROR "MeshLab 2020.09 headers not found in ${MESHLAB2020_SOURCE_DIR}; run scripts/setup")
endif()
find_library(MESHLAB2020_COMMON_LIB meshlab-common PATHS "${MESHLAB2020_LIB_DIR}" NO_DEFAULT_PATH REQUIRED)

find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
find_package(OpenGL REQUIRED)
find_package(GLEW REQUIRED)
find_package(Eigen3 REQUIRED NO_MODULE)

add_library(meshlab_host INTERFACE)
# vcglib and MeshLab headers are third-party: SYSTEM keeps their warnings out of our build.
target_include_directories(meshlab_host SYSTEM INTERFACE
  "${MESHLAB2020_SOURCE_DIR}/src"
  "${MESHLAB2020_SOURCE_DIR}/src/common"
  "${MESHLAB2020_SOURCE_DIR}/vcglib")
target_compile_definitions(meshlab_host INTERFACE MESHLAB_SCALAR=float)
target_link_libraries(meshlab_host INTERFACE
  "${MESHLAB2020_COMMON_LIB}" Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml
  GLEW::GLEW OpenGL::GL Eigen3::Eigen)
