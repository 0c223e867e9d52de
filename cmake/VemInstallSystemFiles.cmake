# Run by `cmake --install` (and cpack), after cmake/VemInstall.cmake's install(CODE) has set:
#   VEM_CONFIG_FILES   config/*.toml          VEM_UNIT_FILE      systemd/vemd.service
#   VEM_UNIT_WORK_DIR  a build-tree folder    VEM_BINDIR, VEM_SYSCONFDIR, VEM_UNITDIR (GNUInstallDirs'
#                                             relative or absolute folders)
# Installs the configuration into <sysconf>/vemcast and the unit into <unitdir>, with the unit's
# ExecStart naming the installed vemd and vemd.toml. Both folders depend on the install prefix,
# known only now: prefix /usr gives /etc and /lib/systemd/system (what the .deb holds), prefix P
# gives P/etc and P/lib/systemd/system. DESTDIR is honoured by file(INSTALL).

# The unit in the source tree is the packaged one (prefix /usr); this is its line to rewrite.
set(packaged_exec_start "ExecStart=/usr/bin/vemd --config /etc/vemcast/vemd.toml")

function(vem_install_dir out relative_or_absolute usr_default)
  if(IS_ABSOLUTE "${relative_or_absolute}")
    set(${out} "${relative_or_absolute}" PARENT_SCOPE)
  elseif(CMAKE_INSTALL_PREFIX STREQUAL "/usr" OR CMAKE_INSTALL_PREFIX STREQUAL "/usr/")
    set(${out} "${usr_default}" PARENT_SCOPE)
  else()
    set(${out} "${CMAKE_INSTALL_PREFIX}/${relative_or_absolute}" PARENT_SCOPE)
  endif()
endfunction()

vem_install_dir(sysconf_dir "${VEM_SYSCONFDIR}" "/etc")
vem_install_dir(unit_dir "${VEM_UNITDIR}" "/lib/systemd/system")
if(IS_ABSOLUTE "${VEM_BINDIR}")
  set(bin_dir "${VEM_BINDIR}")
else()
  string(REGEX REPLACE "/$" "" bin_dir "${CMAKE_INSTALL_PREFIX}/${VEM_BINDIR}")
endif()
set(config_dir "${sysconf_dir}/vemcast")

# The configuration. An existing file that differs (edited by hand) is kept, not overwritten:
# `cmake --install` again must not lose a camera setup. (The .deb's conffiles do this for dpkg.)
foreach(config_file IN LISTS VEM_CONFIG_FILES)
  get_filename_component(name "${config_file}" NAME)
  set(installed "$ENV{DESTDIR}${config_dir}/${name}")
  if(EXISTS "${installed}")
    file(SHA256 "${installed}" installed_hash)
    file(SHA256 "${config_file}" source_hash)
    if(NOT installed_hash STREQUAL source_hash)
      message(STATUS "Kept: ${installed} (it differs from ${config_file}, which was not installed)")
      continue()
    endif()
  endif()
  file(INSTALL DESTINATION "${config_dir}" TYPE FILE PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ
       FILES "${config_file}")
endforeach()

# The unit, its ExecStart rewritten for this prefix (unchanged for /usr).
file(READ "${VEM_UNIT_FILE}" unit)
string(FIND "${unit}" "\n${packaged_exec_start}\n" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${VEM_UNIT_FILE}: expected the line '${packaged_exec_start}', which the install rewrites for the install prefix")
endif()
if("${bin_dir}${config_dir}" MATCHES "[ \t\n]")
  message(FATAL_ERROR "${VEM_UNIT_FILE}: the install prefix '${CMAKE_INSTALL_PREFIX}' holds white space, expected a prefix without any (it goes unquoted into ExecStart)")
endif()
set(exec_start "ExecStart=${bin_dir}/vemd --config ${config_dir}/vemd.toml")
string(REPLACE "\n${packaged_exec_start}\n" "\n${exec_start}\n" unit "${unit}")
# One generated file per destination (DESTDIR and prefix), so that two installs at once (cpack's
# and `cmake --install`'s) never write the same file; rewritten only when its text changes.
string(MD5 destination_tag "$ENV{DESTDIR}|${CMAKE_INSTALL_PREFIX}")
set(generated "${VEM_UNIT_WORK_DIR}/${destination_tag}/vemd.service")
set(previous "")
if(EXISTS "${generated}")
  file(READ "${generated}" previous)
endif()
if(NOT previous STREQUAL unit)
  file(WRITE "${generated}" "${unit}")
endif()
file(INSTALL DESTINATION "${unit_dir}" TYPE FILE PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ
     FILES "${generated}")
