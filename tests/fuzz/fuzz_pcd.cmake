# Included by tests/fuzz/standalone/CMakeLists.txt for fuzz_pcd: the PCD reader goes through
# PCL's pcl_io (the installed, uninstrumented library; VTK hidden as in PlumbDependencies.cmake).
set(CMAKE_DISABLE_FIND_PACKAGE_VTK TRUE)
find_package(PCL 1.13 REQUIRED COMPONENTS common io)
set(CMAKE_DISABLE_FIND_PACKAGE_VTK FALSE)
target_link_libraries(fuzz_pcd PRIVATE pcl_io pcl_common)
