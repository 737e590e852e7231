# OceanInstall: what `cmake --install` lays out (programs, shaders, sky, systemd unit, example
# config, docs) and how CPack turns that tree into the Debian package `ocean`.
# Included last by the top-level CMakeLists.txt, so every target that was configured exists here;
# folders left out with OCEAN_DIRS simply contribute nothing.
include(GNUInstallDirs)

# Programs that read installed data link this to learn where it lives.
add_library(ocean_paths INTERFACE)
target_compile_definitions(ocean_paths INTERFACE OCEAN_INSTALL_DATADIR="${CMAKE_INSTALL_FULL_DATADIR}/ocean")
add_library(ocean::paths ALIAS ocean_paths)

set(OCEAN_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/ocean)

foreach(program ocean-server ocean-viewer ocean-loadtest ocean-bench ocean-simdump)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

# The renderer embeds its shaders; the sources ship for reference and for custom builds.
file(GLOB ocean_shader_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/*.glsl)
if(ocean_shader_sources)
  install(FILES ${ocean_shader_sources} DESTINATION ${OCEAN_DATA_DESTINATION}/shaders)
endif()

# assets/CMakeLists.txt installs the sky it paints into share/ocean/sky, the folder the renderer
# searches (OCEAN_SKY_INSTALL_DIR); only when that folder was not configured do we pick up
# whatever an earlier build left in the build tree.
if(NOT TARGET ocean_sky_assets)
  install(DIRECTORY ${CMAKE_BINARY_DIR}/assets/sky/ DESTINATION ${OCEAN_DATA_DESTINATION}/sky
    OPTIONAL FILES_MATCHING PATTERN "*.png")
endif()

set(ocean_docs README.md server/README-server.md deploy/RUNNING.md)
foreach(doc ${ocean_docs})
  if(EXISTS ${PROJECT_SOURCE_DIR}/${doc})
    install(FILES ${PROJECT_SOURCE_DIR}/${doc} DESTINATION ${CMAKE_INSTALL_DOCDIR})
  endif()
endforeach()

# The systemd unit and the example config. Where they go depends on the prefix, which is only
# known at install time (`cmake --install --prefix`, CPack's /usr): /usr follows GNUInstallDirs'
# rule of configuration in /etc; any other prefix keeps everything under the prefix, so a
# scratch install never writes to the real /etc. The unit's ExecStart is pointed at the
# installed binary.
install(CODE "
set(OCEAN_DEPLOY_SOURCE_DIR \"${PROJECT_SOURCE_DIR}/deploy\")
set(OCEAN_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
set(OCEAN_SYSCONFDIR \"${CMAKE_INSTALL_SYSCONFDIR}\")
set(OCEAN_UNIT_STAGING_DIR \"${CMAKE_CURRENT_BINARY_DIR}/ocean-unit\")
")
install(CODE [[
if(IS_ABSOLUTE "${OCEAN_SYSCONFDIR}")
  set(ocean_etc "${OCEAN_SYSCONFDIR}")
elseif(CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(ocean_etc "/etc")
else()
  set(ocean_etc "${CMAKE_INSTALL_PREFIX}/${OCEAN_SYSCONFDIR}")
endif()
if(IS_ABSOLUTE "${OCEAN_BINDIR}")
  set(ocean_bin "${OCEAN_BINDIR}")
else()
  set(ocean_bin "${CMAKE_INSTALL_PREFIX}/${OCEAN_BINDIR}")
endif()
file(INSTALL DESTINATION "${ocean_etc}/ocean" TYPE FILE FILES "${OCEAN_DEPLOY_SOURCE_DIR}/ocean-server.toml")

file(READ "${OCEAN_DEPLOY_SOURCE_DIR}/ocean-server.service" ocean_unit)
string(REPLACE "/usr/bin/ocean-server" "${ocean_bin}/ocean-server" ocean_unit "${ocean_unit}")
file(WRITE "${OCEAN_UNIT_STAGING_DIR}/ocean-server.service" "${ocean_unit}")
file(INSTALL DESTINATION "${CMAKE_INSTALL_PREFIX}/lib/systemd/system" TYPE FILE
  FILES "${OCEAN_UNIT_STAGING_DIR}/ocean-server.service")
]])

# ---- Debian package -------------------------------------------------------------------------
set(OCEAN_PACKAGE_MAINTAINER "Ocean maintainers <ocean-maintainers@example.org>"
  CACHE STRING "Maintainer field of the Debian package")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ocean)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "Ocean project")
set(CPACK_PACKAGE_CONTACT "${OCEAN_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "spectral ocean simulation server with thin GLES 2 clients")
set(CPACK_PACKAGE_DESCRIPTION
  "ocean-server simulates a Tessendorf/JONSWAP spectral ocean each tick and streams quantized
height deltas over TCP and UDP to lightweight viewers that only displace a cached grid and
shade it. The package holds the server, the tools built with it, a hardened systemd unit and
an example configuration in /etc/ocean.")
# DESTDIR staging makes CPack run the install with the real prefix (/usr), so the unit and the
# config land where the rule above puts them for /usr: /usr/lib/systemd/system and /etc/ocean.
set(CPACK_SET_DESTDIR ON)
if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  # Compiled-in data paths (OCEAN_INSTALL_DATADIR, the renderer's sky folder) follow the
  # configured prefix, while the package installs under /usr.
  message(STATUS "OceanInstall: for a Debian package configure with -DCMAKE_INSTALL_PREFIX=/usr "
                 "(now ${CMAKE_INSTALL_PREFIX}), or the programs will look for data in the wrong place")
endif()
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${OCEAN_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION net)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)

# Maintainer scripts: dpkg keeps local edits of the config (conffiles); postinst creates the
# admin token the unit loads as a credential, so `systemctl enable --now` works right away.
set(ocean_debian_dir ${CMAKE_CURRENT_BINARY_DIR}/debian-control)
file(WRITE ${ocean_debian_dir}/conffiles "/etc/ocean/ocean-server.toml\n")
file(WRITE ${ocean_debian_dir}/postinst [[#!/bin/sh
set -e
if [ "$1" = configure ]; then
  token=/etc/ocean/admin-token
  if [ ! -e "$token" ]; then
    (umask 077 && head -c 32 /dev/urandom | od -An -vtx1 | tr -d ' \n' > "$token")
  fi
  if [ -d /run/systemd/system ]; then
    systemctl daemon-reload >/dev/null || true
  fi
fi
exit 0
]])
file(WRITE ${ocean_debian_dir}/postrm [[#!/bin/sh
set -e
if [ "$1" = purge ]; then
  rm -f /etc/ocean/admin-token
  rmdir /etc/ocean 2>/dev/null || true
fi
if [ -d /run/systemd/system ]; then
  systemctl daemon-reload >/dev/null || true
fi
exit 0
]])
file(CHMOD ${ocean_debian_dir}/postinst ${ocean_debian_dir}/postrm
  PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
  ${ocean_debian_dir}/conffiles ${ocean_debian_dir}/postinst ${ocean_debian_dir}/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
