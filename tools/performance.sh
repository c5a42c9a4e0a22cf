#!/bin/sh
# Reproduces the tables of docs/performance.md: this build against a baseline build, in one run so
# that both see the same machine load.
# Usage: tools/performance.sh BASELINE_BUILD [BUILD]
#   BASELINE_BUILD: a release build of the commit to compare with (it needs apps/cli/luxel and
#                   bench/luxel_bench); BUILD defaults to build/release.
# One core is used for the single-threaded rows (taskset -c 0), two for the others.
set -eu
base=${1:?usage: tools/performance.sh BASELINE_BUILD [BUILD]}
new=${2:-build/release}
scene=scenes/2d/room.json

echo "== HRC, $scene at 1024^2: wall ms per frame, best of 3 (new: per pass)"
for cores in 0 0-1; do
    echo "-- cores $cores, new"
    taskset -c "$cores" "$new/apps/cli/luxel" bench "$scene" --sizes 1024 --repeat 3
    echo "-- cores $cores, baseline"
    taskset -c "$cores" "$base/apps/cli/luxel" bench "$scene" --sizes 1024 --repeat 3
done

echo "== HRC peak memory: luxel render at 2048^2 (and the solve's CPU time)"
out=$(mktemp -d)
for build in "$new" "$base"; do
    /usr/bin/time -f "$build: peak RSS %M KiB, user %U s, wall %e s" \
        "$build/apps/cli/luxel" render "$scene" --solver hrc --size 2048x2048 --out "$out/hrc.exr" \
        >/dev/null
done
echo "== RC on one core: solve seconds (luxel render --stats), best of 3"
for merge in vanilla bilinear-fix; do
    for size in 512 1024; do
        for build in "$new" "$base"; do
            best=
            for run in 1 2 3; do
                t=$(taskset -c 0 "$build/apps/cli/luxel" render "$scene" --solver rc --merge "$merge" \
                    --size "${size}x${size}" --threads 1 --backend cpu --stats -q --out "$out/rc.exr" |
                    sed -n 's/.*solve_seconds[^0-9]*\([0-9.]*\).*/\1/p')
                best=$(printf '%s\n%s\n' "$best" "$t" | sed '/^$/d' | sort -g | head -1)
            done
            echo "rc $merge ${size}^2 $build: $best s"
        done
    done
done
rm -rf "$out"

echo "== Voxel rays against Embree (one thread each, CPU time)"
"$new/bench/luxel_bench" --benchmark_filter='^voxel/' --benchmark_counters_tabular=true \
    --benchmark_repetitions=3 --benchmark_report_aggregates_only=true 2>/dev/null
