#!/bin/sh
# Issue 17, "The tools are not on the PATH": `cmake --install` must put the four tools, the
# configuration, the systemd unit and the documentation where they belong, and nothing else.
# Installs the build into WORK/prefix (and, with DESTDIR, into WORK/destdir as prefix /usr, the
# .deb's layout), then checks the files, runs each installed tool's --help, and checks that the
# unit's ExecStart names the installed vemd and vemd.toml. Needs the four tools built (CI runs it
# after the full build).
# Usage: install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR TOOL_FILE...  (the four built tools)
# Exits 77 (ctest SKIP_RETURN_CODE) when a tool is not built: the sanitizer build folder builds
# only the test targets and some tools.
set -eu
. "$(dirname "$0")/needs_built_tools.sh"
tools="vemd vemtool vemview vemcalib"
configs="vemd.toml camera-example.toml plate-camera-example.toml"

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix

# --- A prefix of our own, as `cmake --install build --prefix DIR` does it -------------------------
cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 ||
  { cat "$work/install.log"; fail "cmake --install $build --prefix $prefix failed (log above)"; }

for tool in $tools; do
  [ -x "$prefix/bin/$tool" ] || fail "$prefix/bin/$tool: expected the installed tool, found none"
  "$prefix/bin/$tool" --help >"$work/$tool-help.txt" 2>&1 ||
    fail "$prefix/bin/$tool --help: expected exit status 0 (output in $work/$tool-help.txt)"
done
# Only the four tools: no tests, benchmarks, generators, static libraries or headers.
extra=$(cd "$prefix" && find . -type f ! -path './bin/vemd' ! -path './bin/vemtool' \
          ! -path './bin/vemview' ! -path './bin/vemcalib' ! -path './etc/vemcast/*.toml' \
          ! -path './lib/systemd/system/vemd.service' ! -path './share/doc/vemcast/*')
[ -z "$extra" ] || fail "$prefix: expected only the tools, config, unit and docs, found also: $extra"

for config in $configs; do
  cmp -s "$source/config/$config" "$prefix/etc/vemcast/$config" ||
    fail "$prefix/etc/vemcast/$config: expected a copy of config/$config"
done

for doc in README.md docs/vemd.md docs/architecture.md docs/images/main-job-render.png \
           examples/mosquitto/vemcast.conf examples/mosquitto/vemcast.acl \
           examples/systemd/vemd-mqtt-broker.conf; do
  [ -f "$prefix/share/doc/vemcast/$doc" ] || fail "$prefix/share/doc/vemcast/$doc: expected the installed documentation, found none"
done

# The unit names the installed vemd and configuration, and is otherwise the source tree's.
unit=$prefix/lib/systemd/system/vemd.service
[ -f "$unit" ] || fail "$unit: expected the installed systemd unit, found none"
expected="ExecStart=$prefix/bin/vemd --config $prefix/etc/vemcast/vemd.toml"
found=$(grep '^ExecStart=' "$unit" || true)
[ "$found" = "$expected" ] || fail "$unit: ExecStart: expected '$expected', found '$found'"
grep -v '^ExecStart=' "$unit" >"$work/unit-rest"
grep -v '^ExecStart=' "$source/systemd/vemd.service" >"$work/source-unit-rest"
cmp -s "$work/unit-rest" "$work/source-unit-rest" ||
  fail "$unit: expected systemd/vemd.service with only ExecStart changed, found other differences"

# Installing again keeps a configuration edited by hand.
echo "# edited by hand" >>"$prefix/etc/vemcast/vemd.toml"
cmake --install "$build" --prefix "$prefix" >"$work/install-again.log" 2>&1 ||
  { cat "$work/install-again.log"; fail "cmake --install $build --prefix $prefix failed the second time (log above)"; }
tail -n 1 "$prefix/etc/vemcast/vemd.toml" | grep -q '^# edited by hand$' ||
  fail "$prefix/etc/vemcast/vemd.toml: expected the edited file kept by a second install, found it overwritten"

# --- Prefix /usr under DESTDIR: the .deb's layout (/etc/vemcast, /lib/systemd/system) -------------
destdir=$work/destdir
DESTDIR=$destdir cmake --install "$build" --prefix /usr >"$work/install-usr.log" 2>&1 ||
  { cat "$work/install-usr.log"; fail "DESTDIR=$destdir cmake --install $build --prefix /usr failed (log above)"; }
for file in usr/bin/vemd usr/bin/vemtool usr/bin/vemview usr/bin/vemcalib etc/vemcast/vemd.toml \
            etc/vemcast/camera-example.toml lib/systemd/system/vemd.service usr/share/doc/vemcast/README.md; do
  [ -f "$destdir/$file" ] || fail "$destdir/$file: expected with prefix /usr, found none"
done
cmp -s "$source/systemd/vemd.service" "$destdir/lib/systemd/system/vemd.service" ||
  fail "$destdir/lib/systemd/system/vemd.service: expected systemd/vemd.service unchanged for prefix /usr"
grep -qx 'ExecStart=/usr/bin/vemd --config /etc/vemcast/vemd.toml' "$source/systemd/vemd.service" ||
  fail "$source/systemd/vemd.service: ExecStart: expected '/usr/bin/vemd --config /etc/vemcast/vemd.toml'"

echo "installed into $prefix and (prefix /usr) $destdir: tools run, config, unit and docs in place"
