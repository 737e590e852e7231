# Helpers shared by every folder: warnings, sanitizers, and the Catch2 test registration.

# Project code is -Wall -Wextra clean; generated and third-party headers are included as SYSTEM.
function(ocean_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(OCEAN_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${OCEAN_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PRIVATE -fsanitize=${OCEAN_SANITIZE})
  endif()
  # OCEAN_FUZZ (clang only): libraries get libFuzzer's coverage instrumentation without its main();
  # tests/fuzz links the harnesses with -fsanitize=fuzzer.
  if(OCEAN_FUZZ AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# ocean_add_test(NAME SOURCES a.cpp b.cpp LIBS lib1 lib2)
# One Catch2 executable whose test cases are each registered with CTest.
# GL: the test drives Mesa (llvmpipe) in its own process. Under ASan its leak check is off
# (tests/sanitizers/no_leak_check.cpp): Mesa unloads its driver at eglTerminate and leaves a few
# allocations behind whose stacks then point into unmapped memory, so no suppression can name
# them. Every other ASan and UBSan check stays on; the code without GL runs with the leak check.
function(ocean_add_test name)
  # PROPERTIES: more CTest properties for every test case of the binary (RUN_SERIAL TRUE, LABELS x).
  cmake_parse_arguments(T "GL" "" "SOURCES;LIBS;PROPERTIES" ${ARGN})
  if(T_GL AND OCEAN_SANITIZE MATCHES "address")
    list(APPEND T_SOURCES ${PROJECT_SOURCE_DIR}/tests/sanitizers/no_leak_check.cpp)
  endif()
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ocean_catch_main ${T_LIBS})
  ocean_target_defaults(${name})
  # One variable only: catch_discover_tests splits a list into separate property arguments.
  catch_discover_tests(${name} TEST_PREFIX "${name}:" DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "OCEAN_BUILD_DIR=${CMAKE_BINARY_DIR}" ${T_PROPERTIES})
endfunction()
