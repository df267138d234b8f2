# Read by ctest after the lists of discovered tests (CMakeLists.txt, TEST_INCLUDE_FILES): gives every
# test of wiggle_tests the label "gtest" beside its own ("unit" or "slow"), so that `ctest -L gtest`
# selects the C++ tests alone, without the scripts labelled "unit" (.ci/run's sanitized step).
# Set here rather than in gtest_discover_tests's PROPERTIES, where CMake 3.25 splits the list
# "unit;gtest" and takes "gtest" for a property's name.
foreach(kind unit slow)
  if(wiggle_${kind}_gtests)
    set_tests_properties(${wiggle_${kind}_gtests} PROPERTIES LABELS "${kind};gtest")
  endif()
endforeach()
