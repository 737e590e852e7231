# OceanWeb: -DOCEAN_BUILD_WEB=ON builds the browser viewer (client/web) with Emscripten as an
# external project of this build, into ${CMAKE_BINARY_DIR}/web - the folder ocean-server's
# --web-root serves by default. It reuses what this build generates: flatc's protocol header, the
# embedded shaders and the sky pictures. Without emcmake on PATH it says so and builds the rest.
find_program(OCEAN_EMCMAKE emcmake)
if(NOT OCEAN_EMCMAKE)
  message(WARNING "OCEAN_BUILD_WEB: emcmake not found (apt install emscripten); the web viewer is not built")
  return()
endif()
if(NOT TARGET ocean_protocol_schema OR NOT TARGET ocean_render_shaders OR NOT TARGET ocean_sky_web_assets)
  message(WARNING "OCEAN_BUILD_WEB: needs the protocol, client/render and assets folders; the web viewer is not built")
  return()
endif()
include(ExternalProject)
include(GNUInstallDirs)
set(OCEAN_WEB_DIR ${CMAKE_BINARY_DIR}/web)
# Debian's emcc runs under the first node on PATH; Debian's node modules must be visible to it.
set(ocean_web_env ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
# A unity build of this tree makes a unity build of the viewer too.
set(ocean_web_unity)
if(CMAKE_UNITY_BUILD)
  set(ocean_web_unity -DCMAKE_UNITY_BUILD=ON)
  if(CMAKE_UNITY_BUILD_BATCH_SIZE)
    list(APPEND ocean_web_unity -DCMAKE_UNITY_BUILD_BATCH_SIZE=${CMAKE_UNITY_BUILD_BATCH_SIZE})
  endif()
endif()
# The viewer's own tree keeps the generator it was first configured with (CMake refuses another).
set(ocean_web_generator ${CMAKE_GENERATOR})
if(EXISTS ${CMAKE_BINARY_DIR}/web-build/CMakeCache.txt)
  file(STRINGS ${CMAKE_BINARY_DIR}/web-build/CMakeCache.txt ocean_web_cached REGEX "^CMAKE_GENERATOR:INTERNAL=")
  string(REPLACE "CMAKE_GENERATOR:INTERNAL=" "" ocean_web_generator "${ocean_web_cached}")
endif()
cmake_host_system_information(RESULT ocean_web_jobs QUERY NUMBER_OF_LOGICAL_CORES)
ExternalProject_Add(ocean_web
  SOURCE_DIR ${PROJECT_SOURCE_DIR}/client/web
  BINARY_DIR ${CMAKE_BINARY_DIR}/web-build
  CONFIGURE_COMMAND ${ocean_web_env} ${OCEAN_EMCMAKE} ${CMAKE_COMMAND} -S <SOURCE_DIR> -B <BINARY_DIR>
    -G ${ocean_web_generator}
    -DCMAKE_BUILD_TYPE=Release
    ${ocean_web_unity}
    -DOCEAN_SOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DOCEAN_PROTOCOL_GENERATED_DIR=${OCEAN_PROTOCOL_GENERATED_DIR}
    -DOCEAN_RENDER_GENERATED_DIR=${OCEAN_RENDER_GENERATED_DIR}
    -DOCEAN_SKY_DIR=${CMAKE_BINARY_DIR}/assets/sky-web
    -DOCEAN_WEB_OUTPUT_DIR=${OCEAN_WEB_DIR}
  BUILD_COMMAND ${ocean_web_env} ${CMAKE_COMMAND} --build <BINARY_DIR> -j ${ocean_web_jobs}
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON  # its own build decides what changed in the shared sources
  DEPENDS ocean_protocol_schema ocean_render_shaders ocean_sky_web_assets)
install(DIRECTORY ${OCEAN_WEB_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ocean/web)
