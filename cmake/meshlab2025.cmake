# meshlab_host for MeshLab 2025.07 as shipped in the pymeshlab 2025.7.post1 wheel (double scalar).
# Headers come from the 2025.07 source in .deps (src/ for common/..., src/vcglib for vcg/ and
# wrap/); the plugin links the wheel's own libmeshlab-common.so and Qt 5.15.2 libraries, so the
# link fails on any symbol the running pymeshlab does not have. Debian's Qt 5.15 headers and moc
# are ABI-compatible with the wheel's Qt 5.15.2 (QPluginLoader only compares major.minor).
set(SLICEREUSE_MESHLAB2025_SOURCE "${CMAKE_CURRENT_SOURCE_DIR}/.deps/meshlab-2025.07"
    CACHE PATH "MeshLab 2025.07 source tree (needs src/common and src/vcglib)")
file(GLOB _slicereuse_wheel_lib "${CMAKE_CURRENT_SOURCE_DIR}/.venv/lib/python3*/site-packages/pymeshlab/lib")
set(SLICEREUSE_PYMESHLAB_LIB "${_slicereuse_wheel_lib}"
    CACHE PATH "The pymeshlab wheel's lib folder (holds libmeshlab-common.so and libQt5*.so.5)")

foreach(f src/common/plugins/interfaces/filter_plugin.h src/vcglib/vcg/complex/complex.h ML_VERSION)
  if(NOT EXISTS "${SLICEREUSE_MESHLAB2025_SOURCE}/${f}")
    message(FATAL_ERROR "MeshLab 2025.07 source incomplete: ${SLICEREUSE_MESHLAB2025_SOURCE}/${f} "
                        "missing; run scripts/setup or set SLICEREUSE_MESHLAB2025_SOURCE")
  endif()
endforeach()
if(NOT EXISTS "${SLICEREUSE_PYMESHLAB_LIB}/libmeshlab-common.so")
  message(FATAL_ERROR "libmeshlab-common.so not found in '${SLICEREUSE_PYMESHLAB_LIB}'; "
                      "run scripts/setup (installs pymeshlab into .venv) or set SLICEREUSE_PYMESHLAB_LIB")
endif()

# MeshLab builds MESHLAB_VERSION from ML_VERSION plus "d" for double builds; the plugin manager
# rejects a plugin whose precision differs or whose version differs in its first 6 characters.
file(STRINGS "${SLICEREUSE_MESHLAB2025_SOURCE}/ML_VERSION" _slicereuse_ml_version LIMIT_COUNT 1)
string(STRIP "${_slicereuse_ml_version}" _slicereuse_ml_version)

find_package(Qt5 5.15 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
find_package(Eigen3 REQUIRED NO_MODULE)
find_path(SLICEREUSE_GLEW_INCLUDE GL/glew.h REQUIRED)

add_library(meshlab_host INTERFACE)
target_include_directories(meshlab_host SYSTEM INTERFACE
  "${SLICEREUSE_MESHLAB2025_SOURCE}/src"
  "${SLICEREUSE_MESHLAB2025_SOURCE}/src/vcglib"
  "${SLICEREUSE_GLEW_INCLUDE}"
  $<TARGET_PROPERTY:Qt5::Core,INTERFACE_INCLUDE_DIRECTORIES>
  $<TARGET_PROPERTY:Qt5::Gui,INTERFACE_INCLUDE_DIRECTORIES>
  $<TARGET_PROPERTY:Qt5::Widgets,INTERFACE_INCLUDE_DIRECTORIES>
  $<TARGET_PROPERTY:Qt5::OpenGL,INTERFACE_INCLUDE_DIRECTORIES>
  $<TARGET_PROPERTY:Qt5::Xml,INTERFACE_INCLUDE_DIRECTORIES>)
target_compile_definitions(meshlab_host INTERFACE
  MESHLAB_SCALAR=double MESHLAB_VERSION=${_slicereuse_ml_version}d SLICEREUSE_MESHLAB_API=2025
  QT_CORE_LIB QT_GUI_LIB QT_WIDGETS_LIB QT_OPENGL_LIB QT_XML_LIB QT_NO_DEBUG)
# Passed through -Wl, so CMake adds no RPATH: inside pymeshlab these libraries are already
# loaded by soname, and an RPATH to the wheel would shadow system libraries (libgomp) elsewhere.
set(_slicereuse_wheel_libs "")
foreach(l libmeshlab-common.so libQt5Widgets.so.5 libQt5Gui.so.5 libQt5Xml.so.5 libQt5Core.so.5)
  list(APPEND _slicereuse_wheel_libs "-Wl,${SLICEREUSE_PYMESHLAB_LIB}/${l}")
endforeach()
target_link_libraries(meshlab_host INTERFACE
  Eigen3::Eigen
  ${_slicereuse_wheel_libs}
  # libmeshlab-common's own dependencies (libexternal-glew.so, ...) live next to it.
  "-Wl,-rpath-link,${SLICEREUSE_PYMESHLAB_LIB}"
  "-Wl,--no-undefined")
