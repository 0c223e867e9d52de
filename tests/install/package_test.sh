#!/bin/sh
# The .deb (`cpack -G DEB`) must hold what a Debian machine needs: the four tools in /usr/bin, the
# configuration in /etc/vemcast as conffiles, the unit in /lib/systemd/system naming /usr/bin/vemd,
# the documentation, Depends from the real libraries, and a postinst that creates the "vemcast"
# user. Packs the build into WORK (no root, no network) and reads the package with dpkg-deb; it
# never installs it. Needs the four tools built (CI runs it after the full build).
# Usage: package_test.sh BUILD_DIR SOURCE_DIR WORK_DIR TOOL_FILE...  (the four built tools)
# Exits 77 (ctest SKIP_RETURN_CODE) when a tool is not built: the sanitizer build folder builds
# only the test targets and some tools.
set -eu
. "$(dirname "$0")/needs_built_tools.sh"

rm -rf "$work"
mkdir -p "$work"
(cd "$build" && cpack -G DEB -B "$work") >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log"; fail "cpack -G DEB in $build failed (log above)"; }
set -- "$work"/vemcast_*.deb
{ [ $# -eq 1 ] && [ -f "$1" ]; } || fail "$work: expected one vemcast_*.deb from cpack, found: $*"
deb=$1

# --- Control fields --------------------------------------------------------------------------------
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = vemcast ] || fail "$deb: Package: expected 'vemcast', found '$(field Package)'"
depends=$(field Depends)
for dep in adduser libc6 libstdc++6 libsystemd0 libopencv-core406; do
  printf '%s\n' "$depends" | tr ',' '\n' | grep -q "^ *$dep\( \|$\)" ||
    fail "$deb: Depends: expected '$dep' (dpkg-shlibdeps, adduser for the postinst), found '$depends'"
done

# --- Files -----------------------------------------------------------------------------------------
dpkg-deb -c "$deb" >"$work/contents.txt"
# "-rwxr-xr-x root/root  123 2026-12-03 14:33 ./usr/bin/vemd" -> "-rwxr-xr-x ./usr/bin/vemd"
awk '{ print $1, $6 }' "$work/contents.txt" >"$work/files.txt"
for tool in vemd vemtool vemview vemcalib; do
  grep -qx -- "-rwxr-xr-x ./usr/bin/$tool" "$work/files.txt" ||
    fail "$deb: expected ./usr/bin/$tool (executable), found none (list in $work/contents.txt)"
done
for file in ./etc/vemcast/vemd.toml ./etc/vemcast/camera-example.toml ./etc/vemcast/plate-camera-example.toml \
            ./lib/systemd/system/vemd.service ./usr/share/doc/vemcast/README.md \
            ./usr/share/doc/vemcast/docs/vemd.md ./usr/share/doc/vemcast/docs/images/main-job-render.png; do
  grep -qx -- "-rw-r--r-- $file" "$work/files.txt" ||
    fail "$deb: expected $file (mode 0644), found none (list in $work/contents.txt)"
done
if grep -E '\./usr/local/|\.a$|\./usr/include/|_tests?$|bench' "$work/files.txt" >"$work/unwanted.txt"; then
  fail "$deb: expected no /usr/local, static libraries, headers, tests or benchmarks, found: $(cat "$work/unwanted.txt")"
fi
owners=$(awk '{ print $2 }' "$work/contents.txt" | sort -u)
[ "$owners" = root/root ] || fail "$deb: expected every file owned by root/root, found: $owners"

# The unit as packaged: the source tree's, which names /usr/bin/vemd and /etc/vemcast/vemd.toml.
dpkg-deb --fsys-tarfile "$deb" | tar -xOf - ./lib/systemd/system/vemd.service >"$work/vemd.service"
grep -qx 'ExecStart=/usr/bin/vemd --config /etc/vemcast/vemd.toml' "$work/vemd.service" ||
  fail "$deb: ./lib/systemd/system/vemd.service: ExecStart: expected '/usr/bin/vemd --config /etc/vemcast/vemd.toml', found '$(grep '^ExecStart=' "$work/vemd.service")'"
cmp -s "$work/vemd.service" "$source/systemd/vemd.service" ||
  fail "$deb: ./lib/systemd/system/vemd.service: expected a copy of systemd/vemd.service"

# --- Control archive: conffiles and the maintainer scripts -------------------------------------------
control=$work/control
dpkg-deb -e "$deb" "$control"
grep '^-.* \./etc/' "$work/files.txt" | awk '{ print substr($2, 2) }' | sort >"$work/etc-files.txt"
sort "$control/conffiles" >"$work/conffiles.txt"
cmp -s "$work/etc-files.txt" "$work/conffiles.txt" ||
  fail "$deb: conffiles: expected every file under /etc ($(tr '\n' ' ' <"$work/etc-files.txt")), found: $(tr '\n' ' ' <"$work/conffiles.txt")"
for script in postinst prerm postrm; do
  [ -x "$control/$script" ] || fail "$deb: expected an executable $script in the control archive, found none"
  cmp -s "$control/$script" "$source/cmake/debian/$script" ||
    fail "$deb: $script: expected a copy of cmake/debian/$script"
done
grep -q 'adduser --system --group --no-create-home --quiet vemcast' "$control/postinst" ||
  fail "$deb: postinst: expected 'adduser --system --group --no-create-home --quiet vemcast'"
if grep -v '^ *#' "$control/postinst" | grep -Eq 'systemctl[^#]*\b(enable|start)\b'; then
  fail "$deb: postinst: expected the service neither enabled nor started, found a systemctl enable or start"
fi

echo "$deb: $(wc -l <"$work/contents.txt") entries, $(wc -c <"$deb") bytes; Depends: $depends"
