# Run by the CTest test "parallel_tsan" (label tsan): configures a second build tree with
# ThreadSanitizer (PLUMB_TSAN, -O1 -g1), builds only two test executables that run the core's
# TBB loops, and runs the tests of those loops:
#   test_features_tsan      voxel grid / region growing / point assignment (segments), MSAC
#                           plane search, segment lines per patch, openings' ray casts;
#   test_registration_icp   the refinement's correspondence search (parallel_for), slide test
#                           (parallel_deterministic_reduce) and target normals (parallel_for).
# Nothing with the UI, I/O, simulation or quality is built: that keeps the cost low (measured
# wall times in tests/unit/tsan/CMakeLists.txt). Inputs: SRC, BIN, DATA.
#
# TBB itself (Debian's libtbb) is not instrumented: ThreadSanitizer cannot see the
# synchronisation inside the scheduler, so tsan_suppressions.txt silences reports from frames
# inside libtbb only. A race between two of our own lambdas on our own data is still reported:
# tsan_canary (a parallel_for with a deliberate data race) must make TSan report, or the run
# fails.
include(${CMAKE_CURRENT_LIST_DIR}/../../second_tree.cmake)
set(tree ${BIN}/tsan)
set(what ThreadSanitizer)
plumb_configure_second_tree(${tree} ${what} -DPLUMB_TSAN=ON)
# Set before the build: gtest_discover_tests runs each test executable once after linking.
set(ENV{TSAN_OPTIONS}
    "halt_on_error=1:second_deadlock_stack=1:suppressions=${CMAKE_CURRENT_LIST_DIR}/tsan_suppressions.txt")
set(tests test_features_tsan test_registration_icp)
plumb_build_in_second_tree(${tree} ${what} ${tests} tsan_canary)
execute_process(COMMAND ${tree}/tests/unit/tsan/tsan_canary RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "WARNING: ThreadSanitizer: data race")
  message(FATAL_ERROR "tsan_canary's deliberate race went unreported (${rc}): the suppressions or "
                      "the build hide races in our own code")
endif()
message(STATUS "tsan_canary: its deliberate race is reported")
# One test per parallel loop of ours, to keep the run short (TSan slows them 5-10x):
#   MSAC hypothesis scoring and inlier blocks (Planes.MsacFindsEveryFaceOfANoisyRoom), the
#   openings' ray casts (Openings.RayTracingFindsTheWindowAndInteriorPoints), the segment
#   detector's voxel grid, point assignment and lines per patch (Segments.RoomEdges..., Voxel*),
#   the refinement's correspondences, target normals and slide test (IcpRefinement.*).
# Not run: Planes.RegionGrowingAlternativeFindsTheWalls, whose PCL normal estimation runs on
# OpenMP (two threads, fixed) inside libpcl_features and libgomp, neither instrumented (TSan
# misses OpenMP's barriers and reports PCL's own buffers); the other Planes/Openings/Segments
# tests run the same loops again on other scenes.
plumb_run_in_second_tree(${tree} test_features_tsan ${what}
                         "--gtest_filter=Planes.MsacFindsEveryFaceOfANoisyRoom:Openings.RayTracingFindsTheWindowAndInteriorPoints:Segments.RoomEdgesAreFoundWithinTwoCentimetres:Voxel*")
plumb_run_in_second_tree(${tree} test_registration_icp ${what} "--gtest_filter=IcpRefinement.*:PointToPlane.*")
