#!/bin/sh
# The .deb's maintainer scripts (cmake/debian/) against fake adduser, getent and systemctl that
# keep a pretend user database in WORK and log every call: postinst creates the system user
# "vemcast" once (idempotent on reconfigure and upgrade) and adds it to "video" when that group
# exists; no script enables or starts vemd, creates or deletes users elsewhere. Nothing on this
# machine changes: the real adduser is not on the PATH the scripts get (it is in /usr/sbin).
# Usage: postinst_test.sh SOURCE_DIR WORK_DIR
set -eu
source=$1
work=$2
fail() { echo "FAIL: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work/bin"
fake=$work/bin
calls=$work/calls.log
db=$work/db            # passwd: one user name a line; group: "name:member,member"

cat >"$fake/getent" <<'FAKE'
#!/bin/sh
# getent DATABASE NAME: 0 and the entry when NAME is in $VEM_FAKE_DB/DATABASE, else 2.
echo "getent $*" >>"$VEM_FAKE_CALLS"
grep -q "^$2\(:\|$\)" "$VEM_FAKE_DB/$1" 2>/dev/null || exit 2
grep "^$2\(:\|$\)" "$VEM_FAKE_DB/$1"
FAKE
cat >"$fake/adduser" <<'FAKE'
#!/bin/sh
# adduser --system [--group] ... NAME, or adduser [--quiet] USER GROUP, on $VEM_FAKE_DB.
echo "adduser $*" >>"$VEM_FAKE_CALLS"
system=no; group=no; ingroup=""; names=""
while [ $# -gt 0 ]; do
  case $1 in
    --system) system=yes ;;
    --group) group=yes ;;
    --ingroup) ingroup=$2; shift ;;
    --*) ;;
    *) names="$names $1" ;;
  esac
  shift
done
set -- $names
if [ $system = yes ]; then
  grep -qx "$1" "$VEM_FAKE_DB/passwd" && exit 0          # an existing system user: left alone
  if [ $group = yes ]; then                                # like adduser 3.134: refused
    grep -q "^$1:" "$VEM_FAKE_DB/group" && { echo "adduser: the group $1 already exists" >&2; exit 1; }
    echo "$1:" >>"$VEM_FAKE_DB/group"
  fi
  if [ -n "$ingroup" ]; then
    grep -q "^$ingroup:" "$VEM_FAKE_DB/group" || { echo "adduser: no group $ingroup" >&2; exit 1; }
  fi
  echo "$1" >>"$VEM_FAKE_DB/passwd"
  exit 0
fi
[ $# -eq 2 ] || { echo "adduser: expected USER GROUP" >&2; exit 1; }
grep -qx "$1" "$VEM_FAKE_DB/passwd" || { echo "adduser: no user $1" >&2; exit 1; }
grep -q "^$2:" "$VEM_FAKE_DB/group" || { echo "adduser: no group $2" >&2; exit 1; }
grep -q "^$2:.*\b$1\b" "$VEM_FAKE_DB/group" && exit 0   # already a member
sed -i "s/^$2:\(.*\)/$2:\1,$1/; s/^$2:,/$2:/" "$VEM_FAKE_DB/group"
FAKE
for tool in systemctl deluser delgroup useradd groupadd usermod userdel; do
  # shellcheck disable=SC2016  # $* and $VEM_FAKE_CALLS belong to the fake, expanded when it runs
  printf '#!/bin/sh\necho "%s $*" >>"$VEM_FAKE_CALLS"\n' "$tool" >"$fake/$tool"
done
chmod +x "$fake"/*
export VEM_FAKE_CALLS="$calls" VEM_FAKE_DB="$db"
fake_path=$fake:/usr/bin:/bin
for tool in getent adduser systemctl; do
  [ "$(PATH=$fake_path command -v $tool)" = "$fake/$tool" ] ||
    fail "$fake/$tool: expected the fake $tool first on the PATH, found $(PATH=$fake_path command -v $tool)"
done

# run SCRIPT ARGS...: the packaged script as dpkg runs it (sh, from /), with the fakes.
run() {
  script=$1; shift
  (cd / && PATH=$fake_path sh "$source/cmake/debian/$script" "$@") >>"$work/output.log" 2>&1 ||
    fail "cmake/debian/$script $*: expected exit status 0, found $? (output in $work/output.log)"
}
reset_db() { cat "$calls" >>"$work/all-calls.log" 2>/dev/null || true; rm -rf "$db" "$calls"; mkdir -p "$db"; printf 'root\n' >"$db/passwd"; printf 'root:\n%s' "$1" >"$db/group"; : >"$calls"; }
count() { grep -c -- "$1" "$calls" || true; }

# A fresh install on a machine with a "video" group.
reset_db 'video:
'
run postinst configure ""
[ "$(count '^adduser --system --group --no-create-home --quiet vemcast$')" = 1 ] ||
  fail "postinst configure: expected one 'adduser --system --group --no-create-home --quiet vemcast', found: $(cat "$calls")"
grep -qx vemcast "$db/passwd" || fail "postinst configure: expected the user vemcast created, found none"
grep -q '^vemcast:' "$db/group" || fail "postinst configure: expected the group vemcast created, found none"
grep -q '^video:.*vemcast' "$db/group" || fail "postinst configure: expected vemcast in group video, found: $(grep '^video:' "$db/group")"

# Reconfigure and upgrade: the user exists, nothing is created twice, nothing fails.
run postinst configure ""
run postinst configure 0.1.0
[ "$(count '^adduser --system')" = 1 ] ||
  fail "postinst configure (again): expected no second 'adduser --system', found: $(cat "$calls")"
[ "$(grep -c '^vemcast' "$db/passwd")" = 1 ] || fail "postinst configure (again): expected one user vemcast, found $(grep -c '^vemcast' "$db/passwd")"

# Where systemd runs, postinst reloads it (and try-restarts on upgrade); here it may not run.
if [ -d /run/systemd/system ]; then
  [ "$(count '^systemctl daemon-reload')" -ge 1 ] ||
    fail "postinst configure: expected 'systemctl daemon-reload' where systemd runs, found: $(cat "$calls")"
else
  [ "$(count '^systemctl')" = 0 ] ||
    fail "postinst configure: expected no systemctl call where systemd does not run, found: $(cat "$calls")"
fi

# A machine without a "video" group: the user is made, the group is not asked for.
reset_db ''
run postinst configure ""
grep -qx vemcast "$db/passwd" || fail "postinst configure (no video group): expected the user vemcast created, found none"
[ "$(count '^adduser --quiet vemcast video')" = 0 ] ||
  fail "postinst configure (no video group): expected no 'adduser vemcast video', found: $(cat "$calls")"

# A group "vemcast" left without its user (by an admin, or an older install): the user joins it.
reset_db 'vemcast:
video:
'
run postinst configure ""
[ "$(count '^adduser --system --ingroup vemcast --no-create-home --quiet vemcast$')" = 1 ] ||
  fail "postinst configure (group vemcast exists): expected 'adduser --system --ingroup vemcast --no-create-home --quiet vemcast', found: $(cat "$calls")"
grep -qx vemcast "$db/passwd" || fail "postinst configure (group vemcast exists): expected the user vemcast created, found none"

# Removal, purge, failed-upgrade paths: exit 0, no user created or deleted.
reset_db 'video:
'
run prerm remove
run prerm upgrade 0.1.0
run postrm remove
run postrm purge
run postrm upgrade 0.1.0
run postinst abort-upgrade 0.1.0
if grep -E '^(adduser|deluser|delgroup|useradd|groupadd|usermod|userdel) ' "$calls" >"$work/user-calls.txt"; then
  fail "prerm/postrm/postinst abort-upgrade: expected no user or group changed, found: $(cat "$work/user-calls.txt")"
fi

# No script ever enables or starts the service.
cat "$calls" >>"$work/all-calls.log"
if grep -E '^systemctl .*\b(enable|start)\b' "$work/all-calls.log" >"$work/enable-calls.txt"; then
  fail "maintainer scripts: expected vemd neither enabled nor started, found: $(cat "$work/enable-calls.txt")"
fi
echo "postinst creates vemcast once (in video when it exists); prerm/postrm touch no user; nothing enables vemd"
