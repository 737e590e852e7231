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
function(ocean_add_test name)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ocean_catch_main ${T_LIBS})
  ocean_target_defaults(${name})
  catch_discover_tests(${name} TEST_PREFIX "${name}:" DISCOVERY_TIMEOUT 60
    PROPERTIES ENVIRONMENT "OCEAN_BUILD_DIR=${CMAKE_BINARY_DIR};OCEAN_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
endfunction()
