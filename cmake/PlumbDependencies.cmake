# Every third-party dependency is a Debian 12 package (README.md lists them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(assimp REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(pugixml REQUIRED)
find_package(CLI11 REQUIRED)
find_package(CGAL REQUIRED)
find_package(PROJ 9 REQUIRED CONFIG)  # coordinate systems: EPSG codes to WKT (LAS 1.4)

# IFC++ (libifcplusplus-dev, no CMake config): the IFC reader plumb-import falls back to when
# assimp cannot read an IFC. Its headers are many and noisy: included as system headers.
find_path(IFCPP_INCLUDE_DIR ifcpp/reader/ReaderSTEP.h REQUIRED)
find_library(IFCPP_LIBRARY IfcPlusPlus PATH_SUFFIXES ifcplusplus REQUIRED)
find_library(CARVE_LIBRARY carve PATH_SUFFIXES ifcplusplus REQUIRED)
add_library(ifcpp::ifcpp INTERFACE IMPORTED)
target_include_directories(ifcpp::ifcpp SYSTEM INTERFACE ${IFCPP_INCLUDE_DIR})
target_link_libraries(ifcpp::ifcpp INTERFACE ${IFCPP_LIBRARY} ${CARVE_LIBRARY})

# PCL's config asks VTK for GUISupportQt, which Debian builds against Qt5 and which would
# poison this Qt6 project (docs/QT_VTK.md). Hide VTK from PCL: its targets then link no VTK.
set(CMAKE_DISABLE_FIND_PACKAGE_VTK TRUE)
find_package(PCL 1.13 REQUIRED COMPONENTS common io kdtree search features filters
             segmentation sample_consensus registration surface octree)
set(CMAKE_DISABLE_FIND_PACKAGE_VTK FALSE)

if(PLUMB_BUILD_UI)
  find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Test Concurrent Svg)
  find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel CommonColor RenderingCore
               RenderingOpenGL2 RenderingFreeType RenderingAnnotation InteractionStyle
               InteractionWidgets FiltersSources FiltersCore FiltersGeneral IOImage)
endif()
if(PLUMB_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
