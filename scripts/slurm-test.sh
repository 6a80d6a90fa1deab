#!/usr/bin/env bash
# The cluster recipes tested on a real Slurm: a throwaway one-node cluster on this machine (Debian's slurm-wlm
# and munge, installed when missing), configured in a temporary folder with its own ports, state, spool, key
# and socket, never touching /etc/slurm, /etc/munge or the machine's own daemons, and removed on exit, also on
# failure. Then, with the very files the README shows (scripts/slurm/*.sbatch):
#   1. a render as a job array equals a single-process render byte for byte;
#   2. a stability sweep as a job array of shards, merged, equals a single-process sweep byte for byte;
#   3. a render task cancelled mid-way (scancel) and resubmitted alone still gives identical bytes.
#
#   scripts/slurm-test.sh            (as root, or with sudo for the package install; uses build/linkage,
#                                     building it first if it is missing)
# Exit status 0 when all three hold; every wait is bounded, and the summary line gives each phase's time.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)

say() { printf 'slurm-test: %s\n' "$*" >&2; }
fail() {
  say "FAILED: $*"
  exit 1
}
now() { date +%s.%N; }
since() { python3 -c "print(f'{$(now) - $1:.1f}')"; }
started=$(now)

# --- what the test needs
missing=()
for p in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  "${as_root[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ ! -x build/linkage ]; then
  say "building build/linkage"
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build --target linkage >/dev/null
fi
linkage="$root/build/linkage"

# --- a one-node cluster in a temporary folder
work=$(mktemp -d /tmp/linkage-slurm.XXXXXX)
chmod 700 "$work"
daemons=()
cleanup() {
  local status=$?
  for pid in "${daemons[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${daemons[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  if [ $status -ne 0 ]; then
    for log in "$work"/*.log; do [ -f "$log" ] && { say "--- $(basename "$log") (last lines)"; tail -n 15 "$log" >&2; }; done
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Free ports above the usual Slurm ones (6817-6819), picked by the kernel.
read -r ctld_port slurmd_port < <(python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])')
node=$(hostname)
cpus=$(nproc)
memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
mkdir -p "$work/state" "$work/spool" "$work/jobs"
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" --pid-file="$work/munged.pid" \
  --log-file="$work/munged.log" --seed-file="$work/munged.seed"
for _ in $(seq 50); do [ -s "$work/munged.pid" ] && break; sleep 0.1; done
[ -s "$work/munged.pid" ] || fail "munged did not start"
daemons+=("$(cat "$work/munged.pid")")

cat >"$work/slurm.conf" <<EOF
ClusterName=linkage-test
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=300
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
: >"$work/cgroup.conf"  # present and empty: slurmd reads it, and no cgroup plugin is used
export SLURM_CONF="$work/slurm.conf"
slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.out" 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" >"$work/slurmd.out" 2>&1 &
daemons+=($!)
for _ in $(seq 120); do
  state=$(sinfo -h -N -o '%T' 2>/dev/null | head -n 1 || true)
  [[ "$state" == idle* ]] && break
  sleep 0.5
done
[[ "${state:-}" == idle* ]] || fail "the node did not come up (state '${state:-none}')"
say "cluster up: node $node, $cpus CPUs, ports $ctld_port/$slurmd_port ($(since "$started") s)"

# Runs sbatch in the jobs folder with a time limit; --wait makes it return when the job (array) has ended.
submit() { (cd "$work/jobs" && timeout 900 sbatch --parsable "$@"); }
# Byte-for-byte comparison of two folders: same file names, same contents.
same_folders() {
  (cd "$1" && find . -type f -not -name '.*' | sort) >"$work/a.list"
  (cd "$2" && find . -type f -not -name '.*' | sort) >"$work/b.list"
  cmp -s "$work/a.list" "$work/b.list" || return 1
  while read -r file; do cmp -s "$1/$file" "$2/$file" || { say "differs: $file"; return 1; }; done <"$work/a.list"
}
export LINKAGE="$linkage"
scene="$root/scenes/default.json"
size=320x180

# --- 1. a render as a job array
t=$(now)
submit --wait --array=1-4 "$root/scripts/slurm/render-array.sbatch" "$scene" --size $size --out "$work/array" \
  --quiet >/dev/null || fail "the render array failed"
"$linkage" render "$scene" --size $size --out "$work/single" --quiet
same_folders "$work/array" "$work/single" || fail "the render array differs from a single render"
frames=$(find "$work/array" -name 'frame_*.png' | wc -l)
render_time=$(since "$t")
say "1. render array (4 tasks, $frames frames) equals a single render byte for byte ($render_time s)"

# --- 2. a stability sweep as a job array of shards, merged
t=$(now)
sweep=(--kind pole --grid 12 --methods ambient,christoffel)
"$linkage" stability --help | grep -q -- '--methods' || sweep=(--kind pole --grid 12)
# The same relative --out from two working folders: the chart scripts name their files by that path.
submit --wait --array=1-4 "$root/scripts/slurm/stability-array.sbatch" "${sweep[@]}" --out sweep \
  >/dev/null || fail "the stability array failed"
(cd "$work/jobs" && "$linkage" stability "${sweep[@]}" --out sweep --merge --quiet)
mkdir -p "$work/one"
(cd "$work/one" && "$linkage" stability "${sweep[@]}" --out sweep --quiet)
for file in "$work"/one/sweep/*; do
  name=$(basename "$file")
  cmp -s "$file" "$work/jobs/sweep/$name" || fail "merged sweep differs from a single sweep: $name"
done
[ -n "$(ls "$work/one/sweep")" ] || fail "the single sweep wrote nothing"
sweep_time=$(since "$t")
say "2. stability array (4 shards) merged equals a single sweep byte for byte ($sweep_time s)"

# --- 3. one render task cancelled mid-way, resubmitted alone
t=$(now)
slow=(--size 960x540 --out "$work/cancelled" --quiet)
job=$(submit --array=1-2 "$root/scripts/slurm/render-array.sbatch" "$scene" "${slow[@]}")
job=${job%%;*}
# Wait until task 2 has written some of its frames (301..600), then cancel it.
for _ in $(seq 600); do
  written=$({ find "$work/cancelled" -name 'frame_0031*.png' 2>/dev/null || true; } | wc -l)
  [ "$written" -gt 0 ] && break
  sleep 0.1
done
[ "${written:-0}" -gt 0 ] || fail "task 2 wrote nothing to cancel"
scancel "${job}_2"
for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.2
done
[ -z "$(squeue -h -j "$job" 2>/dev/null)" ] || fail "the array did not end after scancel"
done_before=$({ find "$work/cancelled" -name 'frame_00[3-5]*.png' -o -name 'frame_0060*.png' || true; } | wc -l)
[ "$done_before" -lt 300 ] || fail "task 2 had finished before it was cancelled ($done_before frames)"
SHARDS=2 submit --wait --array=2 "$root/scripts/slurm/render-array.sbatch" "$scene" "${slow[@]}" >/dev/null ||
  fail "the resubmitted task failed"
"$linkage" render "$scene" --size 960x540 --out "$work/cancelled-single" --quiet
same_folders "$work/cancelled" "$work/cancelled-single" ||
  fail "the render with a cancelled and resubmitted task differs from a single render"
cancel_time=$(since "$t")
say "3. task 2 cancelled after $done_before of its 300 frames, resubmitted alone: identical to a single render ($cancel_time s)"

say "all 3 checks held in $(since "$started") s (render array $render_time s, sweep $sweep_time s, cancel and resubmit $cancel_time s)"
