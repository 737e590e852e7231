# Helpers shared by every folder: warnings, sanitizers, and the Catch2 test registration.

# Project code is -Wall -Wextra clean; generated and third-party headers are included as SYSTEM.
function(ocean_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(OCEAN_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${OCEAN_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=${OCEAN_SANITIZE})
    # Code that must know (tests that assert timing or memory) asks this, not the compiler's own
    # macros: g++ defines __SANITIZE_ADDRESS__, clang only answers __has_feature.
    target_compile_definitions(${target} PRIVATE OCEAN_SANITIZED=1)
  endif()
  # OCEAN_FUZZ (clang only): libraries get libFuzzer's coverage instrumentation without its main();
  # tests/fuzz links the harnesses with -fsanitize=fuzzer.
  if(OCEAN_FUZZ AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# CPU budgets for CTest. Most tests wait far more than they compute (a real-time load test runs
# a server and its clients at a tenth of a core for seconds), a few take whole cores (the soak,
# software rendering). Each test declares the share of the machine it may take, in hundredths of
# a core ("cpu" slots: 100 per core, in ctest-resources.json, which every ctest in the tree reads),
# so that `ctest -j8` runs as many waiting tests side by side as fit, and never more computing ones
# than there are cores. A budget larger than the machine is the whole machine.
cmake_host_system_information(RESULT OCEAN_TEST_CORES QUERY NUMBER_OF_LOGICAL_CORES)
math(EXPR OCEAN_TEST_CPU_SLOTS "100 * ${OCEAN_TEST_CORES}")
function(ocean_cpu_budget out cpu)
  if(cpu GREATER OCEAN_TEST_CPU_SLOTS)
    set(cpu ${OCEAN_TEST_CPU_SLOTS})
  endif()
  set(${out} "cpu:${cpu}" PARENT_SCOPE)
endfunction()

# ocean_test_budget(TESTS a b CPU n [COST seconds]): the budget of tests added with add_test. COST
# is the test's usual duration: CTest starts the longest first, so a long one does not end a run
# alone.
function(ocean_test_budget)
  cmake_parse_arguments(B "" "CPU;COST" "TESTS" ${ARGN})
  ocean_cpu_budget(groups ${B_CPU})
  set_tests_properties(${B_TESTS} PROPERTIES RESOURCE_GROUPS "${groups}")
  if(B_COST)
    set_tests_properties(${B_TESTS} PROPERTIES COST ${B_COST})
  endif()
endfunction()

# ocean_add_test(NAME SOURCES a.cpp b.cpp LIBS lib1 lib2 [CPU n] [COST s])
# One Catch2 executable whose test cases are each registered with CTest, each with a budget of
# CPU hundredths of a core (default 100: unit tests compute flat out) and an expected COST.
# GL: the test drives Mesa (llvmpipe) in its own process. Under ASan its leak check is off
# (tests/sanitizers/no_leak_check.cpp): Mesa unloads its driver at eglTerminate and leaves a few
# allocations behind whose stacks then point into unmapped memory, so no suppression can name
# them. Every other ASan and UBSan check stays on; the code without GL runs with the leak check.
function(ocean_add_test name)
  # PROPERTIES: more CTest properties for every test case of the binary (LABELS x).
  cmake_parse_arguments(T "GL" "CPU;COST" "SOURCES;LIBS;PROPERTIES" ${ARGN})
  if(T_GL AND OCEAN_SANITIZE MATCHES "address")
    list(APPEND T_SOURCES ${PROJECT_SOURCE_DIR}/tests/sanitizers/no_leak_check.cpp)
  endif()
  if(NOT T_CPU)
    set(T_CPU 100)
  endif()
  # Under TSan a test that mostly waits in Release (a quarter core) computes 5-15x more: eight of
  # them side by side starved each other's servers past their answers' deadlines (CI, 2026-11-29:
  # a HeightQuery unanswered in 20 s, its network thread 76 % waiting for a CPU). Half a core each.
  if(OCEAN_SANITIZE MATCHES "thread" AND T_CPU LESS 50)
    set(T_CPU 50)
  endif()
  ocean_cpu_budget(groups ${T_CPU})
  if(T_COST)
    list(APPEND T_PROPERTIES COST ${T_COST})
  endif()
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ocean_catch_main ${T_LIBS})
  ocean_target_defaults(${name})
  # One variable only: catch_discover_tests splits a list into separate property arguments.
  catch_discover_tests(${name} TEST_PREFIX "${name}:" DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "OCEAN_BUILD_DIR=${CMAKE_BINARY_DIR}" RESOURCE_GROUPS "${groups}" ${T_PROPERTIES})
endfunction()
