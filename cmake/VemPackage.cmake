# The Debian package: `cpack -G DEB` in the build folder makes vemcast_<version>_<arch>.deb from
# what cmake/VemInstall.cmake installs, with prefix /usr:
#   /usr/bin/{vemd,vemtool,vemview,vemcalib}, /etc/vemcast/*.toml (conffiles),
#   /lib/systemd/system/vemd.service, /usr/share/doc/vemcast/
# and the maintainer scripts in cmake/debian/: postinst creates the system user "vemcast" (in
# group "video") and reloads systemd; the service is neither enabled nor started. cpack packs the
# binaries as they are in the build folder (with Ninja it builds nothing first): build, then pack.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME vemcast)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "live lighting capture: an HDR environment map in, directional lights out")
set(CPACK_PACKAGE_DESCRIPTION
    "vemd captures HDR fisheye frames and turns them into a small set of directional lights, frame after frame (Havran et al. 2005), for render clients over a WebSocket stream; vemtool, vemcalib and vemview record, calibrate and render.")
set(VEM_PACKAGE_CONTACT "vemcast maintainers <root@localhost>" CACHE STRING
    "Maintainer field of the .deb (name <address>)")
set(CPACK_PACKAGE_CONTACT "${VEM_PACKAGE_CONTACT}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)                   # vemcast_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION video)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Depends: the shared libraries the four tools link, as dpkg-shlibdeps (dpkg-dev) finds them
# from their packages' shlibs and symbols files, plus adduser for the postinst.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "adduser")
# The binaries go in as built (Release, no debug information, symbols kept for backtraces).

# conffiles: every configuration file, so that dpkg keeps an edited one on upgrade and asks.
set(VEM_PACKAGE_CONTROL_DIR ${PROJECT_BINARY_DIR}/debian)
set(conffiles "")
foreach(config_file IN LISTS VEM_INSTALL_CONFIG_FILES)
  get_filename_component(name ${config_file} NAME)
  string(APPEND conffiles "/etc/vemcast/${name}\n")
endforeach()
file(CONFIGURE OUTPUT ${VEM_PACKAGE_CONTROL_DIR}/conffiles CONTENT "${conffiles}" @ONLY)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/postinst
    ${PROJECT_SOURCE_DIR}/cmake/debian/prerm ${PROJECT_SOURCE_DIR}/cmake/debian/postrm
    ${VEM_PACKAGE_CONTROL_DIR}/conffiles)
# Maintainer scripts 0755, conffiles 0644, whatever the checkout's modes.
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)

include(CPack)
