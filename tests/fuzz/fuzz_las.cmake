# Included by tests/fuzz/standalone/CMakeLists.txt for fuzz_las: the LAS writer's coordinate
# systems go through PROJ (las_crs.cpp; the installed, uninstrumented library).
find_package(PROJ 9 REQUIRED CONFIG)
target_link_libraries(fuzz_las PRIVATE PROJ::proj)
