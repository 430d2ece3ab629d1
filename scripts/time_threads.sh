#!/usr/bin/env bash
# Times one sequence on 1 and on 2 threads (docs/datasets.md, "One sequence on several threads"):
# ROUNDS rounds of the same command alternating --threads 1 and --threads 2, then the medians.
# Per run: "run" is frames / eval_frames_per_s of the printed summary (the run loop), "command"
# the whole process, "cpu" its user + system CPU, "others" the cores other processes kept busy
# meanwhile (from /proc/stat), "load" the 1-minute load average before it. With --pair, the
# machine's own ceiling instead: one --threads 1 run alone against two at once (two processes).
# IDLE_WAIT=S: before each round, wait up to S seconds until other processes use under 0.15 cores
# (over 5 s), for a machine shared with others.
# Usage: [IDLE_WAIT=S] bash scripts/time_threads.sh [--pair] ROUNDS rpt-arguments...
#   bash scripts/time_threads.sh 5 eval --dataset synthetic --param frames=20000
#   bash scripts/time_threads.sh --pair 4 eval --dataset synthetic --param frames=10000
set -euo pipefail
cd "$(dirname "$0")/.."
RPT="${RPT:-build/rpt}"
pair=0
if [ "${1:-}" = "--pair" ]; then
  pair=1
  shift
fi
rounds="$1"
shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
hz=$(getconf CLK_TCK)
busy() { awk '/^cpu /{print $2 + $3 + $4 + $7 + $8 + $9}' /proc/stat; }

# One timed process, its summary in DIR.json and "wall user sys" in DIR.time.
run_one() {  # DIR THREADS
  /usr/bin/time -f "%e %U %S" -o "$1.time" "$RPT" "${args[@]}" --threads "$2" --json --quiet --out "$1" \
    > "$1.json" 2> /dev/null || true
}
# "wall cpu run" of a timed process (run = NA without a summary).
result() {  # DIR
  python3 -c 'import json, sys
w, u, s = open(sys.argv[1] + ".time").read().split()[-3:]
try:
    j = json.load(open(sys.argv[1] + ".json")); run = "%.4f" % (j["frames"] / j["eval_frames_per_s"])
except Exception:
    run = "NA"
print(w, "%.2f" % (float(u) + float(s)), run)' "$1"
}
now() { date +%s.%N; }
wait_idle() {
  local end=$((SECONDS + ${IDLE_WAIT:-0})) b0 b1
  while [ $SECONDS -lt $end ]; do
    b0=$(busy)
    sleep 5
    b1=$(busy)
    python3 -c "import sys; sys.exit(0 if ($b1 - $b0) / $hz / 5 < 0.15 else 1)" && return 0
  done
  return 0  # not idle: time anyway (the "others" column says so)
}
# Cores other processes used between two /proc/stat samples: BUSY0 BUSY1 T0 T1 OUR_CPU_SECONDS.
others() { python3 -c "print('%.2f' % max(0.0, (($2 - $1) / $hz - $5) / ($4 - $3)))"; }

args=("$@")
echo "rpt ${args[*]}; $(nproc) cores; $(uptime)"
for r in $(seq 1 "$rounds"); do
  wait_idle
  if [ "$pair" = 0 ]; then
    for t in 1 2; do
      load=$(cut -d' ' -f1 /proc/loadavg)
      b0=$(busy) t0=$(now)
      run_one "$out/t$t" "$t"
      b1=$(busy) t1=$(now)
      read -r wall cpu run < <(result "$out/t$t")
      echo "threads $t round $r run $run command $wall cpu $cpu others $(others "$b0" "$b1" "$t0" "$t1" "$cpu") load $load"
    done
  else
    load=$(cut -d' ' -f1 /proc/loadavg)
    b0=$(busy) t0=$(now)
    run_one "$out/alone" 1
    b1=$(busy) t1=$(now)
    read -r wall cpu run < <(result "$out/alone")
    echo "alone round $r command $wall cpu $cpu others $(others "$b0" "$b1" "$t0" "$t1" "$cpu") load $load"
    load=$(cut -d' ' -f1 /proc/loadavg)
    b0=$(busy) t0=$(now)
    run_one "$out/a" 1 &
    run_one "$out/b" 1
    wait
    b1=$(busy) t1=$(now)
    read -r wall_a cpu_a run_a < <(result "$out/a")
    read -r wall_b cpu_b run_b < <(result "$out/b")
    cpu=$(python3 -c "print('%.2f' % ($cpu_a + $cpu_b))")
    echo "pair round $r command $wall_a $wall_b cpu $cpu others $(others "$b0" "$b1" "$t0" "$t1" "$cpu") load $load"
  fi
done | tee "$out/log"
echo "$(uptime)"
python3 - "$out/log" "$pair" << 'EOF'
import re, statistics, sys
lines = open(sys.argv[1]).read().splitlines()
med = statistics.median
if sys.argv[2] == "0":
    rows = {1: [], 2: []}
    for line in lines:
        m = re.match(r"threads (\d) round \d+ run (\S+) command (\S+) cpu (\S+) others (\S+)", line)
        if m:
            rows[int(m[1])].append([float(x) if x != "NA" else float("nan") for x in m.groups()[1:]])

    def summary(what, one, two):
        r1, r2 = med(x[0] for x in one), med(x[0] for x in two)
        c1, c2 = med(x[1] for x in one), med(x[1] for x in two)
        print(f"{what}: median run: 1 thread {r1:.3f} s, 2 threads {r2:.3f} s ({r1 / r2:.2f}x); "
              f"median command: {c1:.3f} s, {c2:.3f} s ({c1 / c2:.2f}x); "
              f"CPU {med(x[2] for x in one):.2f} s, {med(x[2] for x in two):.2f} s; "
              f"other processes {min(x[3] for x in one + two):.2f} to {max(x[3] for x in one + two):.2f} cores")

    one, two = rows[1], rows[2]
    summary(f"all {len(one)} rounds", one, two)
    quiet = [i for i in range(min(len(one), len(two))) if one[i][3] < 0.1 and two[i][3] < 0.1]
    if quiet:
        summary(f"the {len(quiet)} rounds with other processes under 0.1 cores", [one[i] for i in quiet],
                [two[i] for i in quiet])
else:
    alone, pair = [], []
    for line in lines:
        m = re.match(r"alone round \d+ command (\S+) cpu \S+ others (\S+)", line)
        if m:
            alone.append(float(m[1]))
        m = re.match(r"pair round \d+ command (\S+) (\S+) cpu \S+ others (\S+)", line)
        if m:
            pair.append(max(float(m[1]), float(m[2])))
    a, p = med(alone), med(pair)
    print(f"median: one alone {a:.2f} s, two at once {p:.2f} s: the machine does {2 * a / p:.2f}x the work of one "
          f"thread on two")
EOF
