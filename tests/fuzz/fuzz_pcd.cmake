# Included by tests/fuzz/standalone/CMakeLists.txt for fuzz_pcd: PCL's reader runs in the
# fuzzer's process (core/io/pcd/helper/, which Plumb runs only in plumb-import) through PCL's
# pcl_io (the installed, uninstrumented library; VTK hidden as in PlumbDependencies.cmake);
# readPcd's helper machinery (core/io/isolation/) and the stream are compiled in too.
set(CMAKE_DISABLE_FIND_PACKAGE_VTK TRUE)
find_package(PCL 1.13 REQUIRED COMPONENTS common io)
set(CMAKE_DISABLE_FIND_PACKAGE_VTK FALSE)
file(GLOB _fuzz_pcd_extra ${S}/core/io/pcd/helper/*.cpp ${S}/core/io/isolation/*.cpp)
target_sources(fuzz_pcd PRIVATE ${_fuzz_pcd_extra})
target_link_libraries(fuzz_pcd PRIVATE pcl_io pcl_common)
