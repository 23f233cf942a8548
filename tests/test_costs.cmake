# Read by ctest after the tests gtest_discover_tests found (TEST_INCLUDE_FILES, tests/CMakeLists.txt).
# COST: the longest tests start first, so that a fresh build folder (CI's: no timing history) does
# not end with one of them running alone on one core. Seconds measured in Release on 2 cores. A name
# that is not a test (a test renamed) is ignored.
cmake_policy(VERSION 3.16)
foreach(entry
    "PostProcessing.FilletAndSmoothOnEveryPlannerOverTheContractWorlds|440"
    "Boustrophedon.ValidAndCoversSeededWorlds|59"
    "SmoothStc.PatchesSplitAndReachIntoLargeOpenAreas|53"
    "SmoothStc.RoundedByDefaultInThePipeline|45"
    "SmoothStc.NeededDetoursTurnLessAndCoverAlmostAsMuch|43")
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 cost)
  set_tests_properties("${name}" PROPERTIES COST "${cost}")
endforeach()
