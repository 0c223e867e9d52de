# What `cmake --install` puts where (GNUInstallDirs), all in this one file rather than beside each
# target: the installed set is small and crosses folders (tools from daemon/, calib/ and client/,
# plus config/, systemd/ and docs/), and one list is easier to check against the package
# (tests/install/) than rules spread over five CMakeLists.txt. Only the four tools are installed:
# no tests, benchmarks, static libraries or headers.
#
#   <prefix>/bin/                         vemd, vemtool, vemview, vemcalib
#   <sysconf>/vemcast/                    vemd.toml, camera-example.toml, plate-camera-example.toml (config/)
#   <unitdir>/vemd.service                the systemd unit, its ExecStart naming the installed vemd
#   <prefix>/share/doc/vemcast/           README.md, docs/*.md and their images
#   <prefix>/share/doc/vemcast/examples/  mosquitto/ (an MQTT broker with vemcast's ACLs, config/mosquitto/)
#                                         and systemd/vemd-mqtt-broker.conf (vemd beside a local broker)
#
# <sysconf> and <unitdir> depend on the prefix, which is known only when installing
# (`cmake --install build --prefix DIR`, or cpack's /usr), so cmake/VemInstallSystemFiles.cmake
# computes them then, with GNUInstallDirs' rule for /etc: prefix /usr gives /etc/vemcast and
# /lib/systemd/system (Debian 12's unit folder), any other prefix P gives P/etc/vemcast and
# P/lib/systemd/system. An absolute CMAKE_INSTALL_SYSCONFDIR or VEM_INSTALL_SYSTEMD_UNITDIR
# given at configure time wins.
include(GNUInstallDirs)

set(VEM_INSTALL_SYSTEMD_UNITDIR "lib/systemd/system" CACHE STRING
    "Folder for vemd.service: relative to the install prefix (/lib/systemd/system for prefix /usr) or absolute")

foreach(tool IN ITEMS vemd vemtool vemview vemcalib)
  if(NOT TARGET ${tool})
    message(FATAL_ERROR "cmake/VemInstall.cmake: the tool '${tool}' is not a target of this build, expected all of vemd, vemtool, vemview and vemcalib")
  endif()
endforeach()
install(TARGETS vemd vemtool vemview vemcalib RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# config/*.toml into <sysconf>/vemcast and systemd/vemd.service into <unitdir>, at install time.
file(GLOB VEM_INSTALL_CONFIG_FILES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/config/*.toml)
install(CODE "
  set(VEM_CONFIG_FILES \"${VEM_INSTALL_CONFIG_FILES}\")
  set(VEM_UNIT_FILE \"${PROJECT_SOURCE_DIR}/systemd/vemd.service\")
  set(VEM_UNIT_WORK_DIR \"${PROJECT_BINARY_DIR}/systemd\")
  set(VEM_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
  set(VEM_SYSCONFDIR \"${CMAKE_INSTALL_SYSCONFDIR}\")
  set(VEM_UNITDIR \"${VEM_INSTALL_SYSTEMD_UNITDIR}\")
")
install(SCRIPT ${CMAKE_CURRENT_LIST_DIR}/VemInstallSystemFiles.cmake)

# The documentation, with the images its pages show (about 360 kB in all).
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "*.svg")

# Examples (Debian's place for them): an MQTT broker's configuration and ACLs, and the systemd
# drop-in that runs vemd beside a local broker (docs/protocol.md, "MQTT"; systemd/README.md).
install(FILES ${PROJECT_SOURCE_DIR}/config/mosquitto/vemcast.conf
              ${PROJECT_SOURCE_DIR}/config/mosquitto/vemcast.acl
              ${PROJECT_SOURCE_DIR}/config/mosquitto/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples/mosquitto)
install(FILES ${PROJECT_SOURCE_DIR}/systemd/vemd-mqtt-broker.conf
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples/systemd)
