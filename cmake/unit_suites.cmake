# Registers one ctest test per gtest suite of the unit tests (run after each build of
# unit_tests, as gtest_discover_tests does per test). Each suite runs as
# `unit_tests --suite NAME`, which forks one child per test (tests/unit_main.cpp): every test
# still has a process of its own, without paying the libraries' start-up once per test.
#
# Inputs (-D): EXE the unit_tests binary, OUT the file to write, SIMULATE the simulator
# (NCUBE_SIMULATE for the tests that run it), WORKDIR, SLOW the suites that are not `quick`,
# separated by commas, COSTS pairs of test name and cost (ctest's COST: longest first).
cmake_minimum_required(VERSION 3.20)
execute_process(COMMAND "${EXE}" --gtest_list_tests OUTPUT_VARIABLE listing
                RESULT_VARIABLE listed)
if(NOT listed EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed (${listed})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
string(REPLACE "," ";" SLOW "${SLOW}")
string(REPLACE "," ";" COSTS "${COSTS}")
set(script "")
foreach(line IN LISTS lines)
  # A suite's line starts in column 0 and ends in '.', maybe followed by "  # TypeParam = ...".
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    string(REGEX REPLACE "^.*/" "" bare "${suite}")
    if(bare IN_LIST SLOW)
      set(label unit)
    else()
      set(label unit-quick)
    endif()
    string(APPEND script
      "add_test([=[${suite}]=] [==[${EXE}]==] --suite [==[${suite}]==])\n"
      "set_tests_properties([=[${suite}]=] PROPERTIES WORKING_DIRECTORY [==[${WORKDIR}]==] "
      "ENVIRONMENT [==[NCUBE_SIMULATE=${SIMULATE}]==] TIMEOUT 300 SKIP_RETURN_CODE 77 "
      "LABELS ${label})\n")
    list(FIND COSTS "${suite}" at)
    if(at GREATER -1)
      math(EXPR at "${at} + 1")
      list(GET COSTS ${at} cost)
      string(APPEND script "set_tests_properties([=[${suite}]=] PROPERTIES COST ${cost})\n")
    endif()
  endif()
endforeach()
file(WRITE "${OUT}" "${script}")
