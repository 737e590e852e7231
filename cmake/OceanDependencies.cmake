# All third-party dependencies come from Debian 12 packages (deploy/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
pkg_check_modules(SODIUM REQUIRED IMPORTED_TARGET libsodium)

# Debian's FlatBuffers 2.0.8 ships only the CONFIG package (no flatbuffers_generate_headers).
find_package(FlatBuffers CONFIG REQUIRED)
find_package(spdlog CONFIG REQUIRED)
find_package(tomlplusplus CONFIG QUIET)
find_package(CLI11 CONFIG QUIET)

# Standalone Asio is header-only in Debian (libasio-dev) with no CMake package.
find_path(ASIO_INCLUDE_DIR asio.hpp REQUIRED)
add_library(ocean_asio INTERFACE)
target_include_directories(ocean_asio SYSTEM INTERFACE ${ASIO_INCLUDE_DIR})
# ASIO_DISABLE_STD_ALIGNED_ALLOC: Asio picks aligned_alloc/free or operator new/delete for its
# handler memory per translation unit, depending on whether a libstdc++ header came first; inline
# functions that differ between TUs mix the two (ASan: alloc-dealloc-mismatch). One choice for all.
target_compile_definitions(ocean_asio INTERFACE ASIO_STANDALONE ASIO_NO_DEPRECATED ASIO_DISABLE_STD_ALIGNED_ALLOC)
target_link_libraries(ocean_asio INTERFACE Threads::Threads)
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  target_compile_definitions(ocean_asio INTERFACE ASIO_HAS_CO_AWAIT=1 ASIO_HAS_STD_COROUTINE=1)
endif()
add_library(ocean::asio ALIAS ocean_asio)

# Header-only Debian libraries without a usable CMake package.
find_path(STB_INCLUDE_DIR stb/stb_image_write.h REQUIRED)
add_library(ocean_stb INTERFACE)
target_include_directories(ocean_stb SYSTEM INTERFACE ${STB_INCLUDE_DIR}/stb)
add_library(ocean::stb ALIAS ocean_stb)

find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
add_library(ocean_cli11 INTERFACE)
target_include_directories(ocean_cli11 SYSTEM INTERFACE ${CLI11_INCLUDE_DIR})
add_library(ocean::cli11 ALIAS ocean_cli11)

find_path(TOMLPP_INCLUDE_DIR toml++/toml.h REQUIRED)
add_library(ocean_tomlpp INTERFACE)
target_include_directories(ocean_tomlpp SYSTEM INTERFACE ${TOMLPP_INCLUDE_DIR})
add_library(ocean::tomlpp ALIAS ocean_tomlpp)

if(OCEAN_BUILD_CLIENT)
  find_package(glfw3 CONFIG REQUIRED)
  find_package(glm CONFIG QUIET)
  if(NOT TARGET glm::glm)
    find_path(GLM_INCLUDE_DIR glm/glm.hpp REQUIRED)
    add_library(glm_headers INTERFACE)
    target_include_directories(glm_headers SYSTEM INTERFACE ${GLM_INCLUDE_DIR})
    add_library(glm::glm ALIAS glm_headers)
  endif()
  pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
  pkg_check_modules(GLESV2 REQUIRED IMPORTED_TARGET glesv2)
endif()
