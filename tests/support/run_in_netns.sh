#!/bin/sh
# Runs a command in a network namespace of its own, where only loopback exists (and is up), so
# Aravis's fake GigE Vision camera, any discovery broadcast and any server listening on 0.0.0.0
# stay on 127.0.0.1 and never reach a real network. Exits 77 (CTest's SKIP_RETURN_CODE) when no namespace can be made here.
#   run_in_netns.sh COMMAND [ARGS...]
if unshare -n true 2>/dev/null; then
  exec unshare -n sh -c 'ip link set lo up && exec "$@"' sh "$@"
fi
if unshare -rn true 2>/dev/null; then
  exec unshare -rn sh -c 'ip link set lo up && exec "$@"' sh "$@"
fi
echo "run_in_netns.sh: skipped: cannot create a network namespace (unshare -n needs CAP_SYS_ADMIN," \
     "unshare -rn unprivileged user namespaces); these tests never run on the host's network" >&2
exit 77
