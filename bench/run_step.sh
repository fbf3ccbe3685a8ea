#!/usr/bin/env bash
# Runs the step benchmarks, each against its rival in the same run, into bench/results/:
#
# 1. Ours against Box2D 2.4.1 (Google Benchmark, bench/engine/step_bench.cpp): step.csv.
# 2. The race against Box2D v3 on its own benchmark suite: its ten scenes (compounds,
#    joint_grid, junkyard, large_pyramid, many_pyramids, rain, smash, spinner, tumbler,
#    washer), each stepped as Box2D v3's benchmark app steps it (1/60 s, 4 substeps, continuous
#    on, as many steps as the app takes), at 1 and 2 workers, against our built-in of the same
#    name twice: at Box2D v3's settings (mink_matched: 4 substeps, 30 Hz contacts of damping
#    ratio 10, 3 m/s push-out, joints at 60 Hz and damping ratio 2) and at our own solver
#    defaults (mink_defaults). Sleeping is as in Box2D v3's app in every run: off where the
#    scene turns it off (joint_grid, large_pyramid, many_pyramids), on elsewhere. A scene we
#    have no built-in for is skipped on our side, with a message.
#    Every run is a process of its own (bench/engine/step_race.hpp). The runs of a scene
#    and worker count are interleaved: they take turns of 200 ms, one running while the others
#    are stopped (bench/engine/take_turns.cpp), so a busy moment of a shared machine falls on
#    all alike; at one worker they all run on the same CPU, so a slow core does too; rounds
#    repeat the whole suite. Step times are wall times, as in
#    Box2D v3's app; the first step of a run is not timed, as there, nor the first of each turn.
# 3. What continuous collision costs, per scene and worker count, in a race of its own after
#    each race of part 2: mink_matched against the same with continuous collision off
#    (mink_matched_no_ccd), and Box2D v3 against itself with it off (box2d_v3_no_ccd). Its
#    turns are 8 steps long, not 200 ms, so that every run times the same steps (all but the
#    first of each turn) and step i of one run is paired with step i of its twin a few tens of
#    milliseconds apart; the cost is the median over the paired steps of all rounds of on / off
#    - 1. The two runs of a pair do not do the same work (the scene goes otherwise with
#    continuous collision off), but they step the same scene through the same stretch of its
#    run at the same moment, so neither a busy moment of the machine nor the scene's own
#    changes over its run fall on one of them alone. (Two runs of one binary, paired so, read
#    within 1.5% of each other; as two medians of 200 ms turns they read up to 10% apart.)
#    It writes
#      step_v3.csv          case,size,implementation,median_ns: the median wall time of a step
#                           over the timed steps of all rounds (size: workers; implementation:
#                           box2d_v3, mink_matched or mink_defaults)
#      step_v3_cpu.csv      the same for the CPU time of a step (every thread of the process).
#                           On a busy machine every process waits for a core now and then; a
#                           short step mostly falls between two waits and a long one mostly
#                           does not, so there the median wall time favours the faster engine.
#                           The CPU time leaves the waits out: at 1 worker it is the fair
#                           figure on a busy machine; at 2 it is the work of both workers,
#                           spinning included, not the time a step takes
#      step_v3_ratios.csv   ours / Box2D v3 per scene, one column per setting and worker count
#      step_v3_continuous.csv  case,workers,on_ns,off_ns,cost,total_cost,phase_share,v3_on_ns,
#                           v3_off_ns,v3_cost,v3_total_cost: part 3 for ours and for Box2D v3:
#                           the median steps with continuous collision on and off, the cost
#                           (the median of on / off over paired steps, - 1) and total_cost (the
#                           paired steps' summed times on / off - 1: the whole run's share,
#                           which a slow moment of the machine in one turn moves more);
#                           phase_share: the share of mink_matched's step its continuous phase
#                           takes, measured within each run of part 2
#      step_v3_phases.csv   case,workers,implementation,phase,mean_ms: the mean time per step
#                           of each phase the engine reports (its own names; "step" is the
#                           whole), over the rounds of part 2
#      step_v3.png          those ratios as bars (gnuplot, bench/plot_step_v3.gp)
#      step_v3_memory.csv   case,implementation,peak_kib: the peak resident memory of the
#                           scene's process at the first worker count, the most of its rounds
#      step_v3_counts.csv   case,implementation,bodies,shapes,joints,contacts at the end of the
#                           first round's run at the first worker count (Box2D v3's from
#                           b2World_GetCounters; contacts: contact records, touching or not);
#                           a scene whose counts differ from Box2D v3's is named on stderr
#    Box2D v3 is built from ../shared/rivals/box2d-v3 beside the repository, or from the source
#    tree named by the CMake cache variable MINK_BOX2D_V3_DIR; without it this part prints why
#    and parts 2 and 3 are skipped. The target mink_bench_step_v3 builds their programs.
#
# Usage: bench/run_step.sh BUILD_DIR [Google Benchmark flags for part 1...]
# Environment:
#   MINK_BENCH_STEP_RIVALS="box2d-2.4.1 box2d-v3"   which parts to run (default both)
#   MINK_BENCH_STEP_REPETITIONS=N     part 1: fresh worlds per case and engine (default 3)
#   MINK_BENCH_STEP_V3_ROUNDS=N       parts 2 and 3: rounds over the suite (default 1)
#   MINK_BENCH_STEP_V3_STEPS=N        parts 2 and 3: N steps per run in every scene instead of
#                                     the app's counts, or NAME=N,NAME=N for the named scenes
#   MINK_BENCH_STEP_V3_SCENES="a b"   parts 2 and 3: only these scenes (default: all ten)
#   MINK_BENCH_STEP_V3_WORKERS="1 2"  parts 2 and 3: worker counts (default 1 and 2)
#   MINK_BENCH_STEP_V3_IMPLEMENTATIONS="box2d_v3 mink_matched"   part 2: only these (default:
#                                     box2d_v3 mink_matched mink_defaults; mink_matched_no_ccd
#                                     and box2d_v3_no_ccd may be named too)
#   MINK_BENCH_STEP_V3_TURN_MS=T      part 2: length of a turn in ms (default 200)
#   MINK_BENCH_STEP_V3_COST=off       part 3 skipped (default on)
#   MINK_BENCH_STEP_V3_COST_TURN_STEPS=K  part 3: steps per turn (default 8)
#   MINK_BENCH_STEP_V3_SLEEP=off      parts 2 and 3: sleeping off in every scene of both
#                                     engines (default app: as Box2D v3's app has it)
# A quick run: MINK_BENCH_STEP_RIVALS=box2d-v3 MINK_BENCH_STEP_V3_STEPS=60 bench/run_step.sh build
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_init step "$@"
rivals=${MINK_BENCH_STEP_RIVALS:-box2d-2.4.1 box2d-v3}

if [[ " $rivals " == *" box2d-2.4.1 "* ]]; then
  started=$SECONDS
  "$binary" --csv="$csv" --repetitions="${MINK_BENCH_STEP_REPETITIONS:-3}" "${bench_args[@]}"
  echo "Step benchmark against Box2D 2.4.1 took $((SECONDS - started)) s; wrote $csv"
fi
if [[ " $rivals " != *" box2d-v3 "* ]]; then exit 0; fi

mink_runner=$build_dir/bin/mink_bench_step_v3_mink
v3_runner=$build_dir/bin/mink_bench_step_v3_box2d
for program in mink_bench_step_v3_mink mink_bench_take_turns; do
  if [ ! -x "$build_dir/bin/$program" ]; then
    echo "run_step.sh: $build_dir/bin/$program not found; build the target mink_bench_step_v3" \
      "first" >&2
    exit 1
  fi
done
if [ ! -x "$v3_runner" ]; then
  v3_dir=$(sed -n 's/^MINK_BOX2D_V3_DIR:PATH=//p' "$build_dir/CMakeCache.txt" 2>/dev/null || true)
  echo "run_step.sh: the race against Box2D v3 is skipped: $v3_runner was not built" \
    "(Box2D v3's source tree, MINK_BOX2D_V3_DIR=${v3_dir:-unset}, is missing, or the target" \
    "mink_bench_step_v3 was not built)"
  exit 0
fi

turns_binary=$build_dir/bin/mink_bench_take_turns
# The CPU the one-worker races run on: the last this script may use (taskset lists them).
race_cpu=$(taskset -cp $$ 2>/dev/null | sed -n 's/.*: //p' | tr ',' '\n' | tail -n 1 | sed 's/.*-//')
rounds=${MINK_BENCH_STEP_V3_ROUNDS:-1}
turn_ms=${MINK_BENCH_STEP_V3_TURN_MS:-200}
workers_list=${MINK_BENCH_STEP_V3_WORKERS:-1 2}
sleep_mode=${MINK_BENCH_STEP_V3_SLEEP:-app}
steps_override=${MINK_BENCH_STEP_V3_STEPS:-}
known_implementations="box2d_v3 mink_matched mink_matched_no_ccd mink_defaults box2d_v3_no_ccd"
implementations=${MINK_BENCH_STEP_V3_IMPLEMENTATIONS:-box2d_v3 mink_matched mink_defaults}
cost_race=${MINK_BENCH_STEP_V3_COST:-on}
cost_turn_steps=${MINK_BENCH_STEP_V3_COST_TURN_STEPS:-8}
# Part 3's pairs, each continuous collision on and off.
cost_pairs="mink_matched:mink_matched_no_ccd box2d_v3:box2d_v3_no_ccd"
all_scenes=$("$v3_runner" --list | awk '{ printf "%s ", $1 }')
scenes=${MINK_BENCH_STEP_V3_SCENES:-$all_scenes}
for scene in $scenes; do
  if [[ " $all_scenes " != *" $scene "* ]]; then
    echo "run_step.sh: MINK_BENCH_STEP_V3_SCENES: $scene is not one of: $all_scenes" >&2
    exit 2
  fi
done
for implementation in $implementations; do
  case $implementation in
    box2d_v3 | mink_matched | mink_matched_no_ccd | mink_defaults | box2d_v3_no_ccd) ;;
    *)
      echo "run_step.sh: MINK_BENCH_STEP_V3_IMPLEMENTATIONS: $implementation is not one of" \
        "$known_implementations" >&2
      exit 2
      ;;
  esac
done
if [ -n "$steps_override" ] && ! [[ $steps_override =~ ^[1-9][0-9]*$ ]]; then
  for entry in ${steps_override//,/ }; do
    if [[ " $all_scenes " != *" ${entry%%=*} "* ]] || ! [[ $entry =~ =[1-9][0-9]*$ ]]; then
      echo "run_step.sh: MINK_BENCH_STEP_V3_STEPS: $entry: expected N, or NAME=N with NAME one" \
        "of: $all_scenes" >&2
      exit 2
    fi
  done
fi
for setting in "MINK_BENCH_STEP_V3_ROUNDS=$rounds" "MINK_BENCH_STEP_V3_TURN_MS=$turn_ms"; do
  if ! [[ ${setting#*=} =~ ^[1-9][0-9]*$ ]]; then
    echo "run_step.sh: $setting: expected a positive whole number" >&2
    exit 2
  fi
done
if [ "$cost_race" != on ] && [ "$cost_race" != off ]; then
  echo "run_step.sh: MINK_BENCH_STEP_V3_COST=$cost_race: expected on or off" >&2
  exit 2
fi
if ! [[ $cost_turn_steps =~ ^[1-9][0-9]*$ ]] || [ "$cost_turn_steps" -lt 2 ]; then
  echo "run_step.sh: MINK_BENCH_STEP_V3_COST_TURN_STEPS=$cost_turn_steps: expected a whole" \
    "number of at least 2 (the first step of each turn is not timed)" >&2
  exit 2
fi

# The steps for a scene from MINK_BENCH_STEP_V3_STEPS; nothing for the app's count.
steps_for() {
  local scene=$1 entry
  if [[ $steps_override =~ ^[0-9]+$ ]]; then
    echo "$steps_override"
    return
  fi
  for entry in ${steps_override//,/ }; do
    if [ "${entry%%=*}" = "$scene" ]; then echo "${entry#*=}"; fi
  done
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
first_workers=${workers_list%% *}
failed=""
started=$SECONDS
echo "Race against Box2D v3: $rounds round(s), workers: $workers_list, turns of $turn_ms ms," \
  "sleeping: $sleep_mode"
# race ROUND SCENE WORKERS KIND COMMAND... (the take-turns commands): runs them and sorts their
# output; KIND main keeps the race and phase lines for part 2's files, cost only prints them.
race() {
  local round=$1 scene=$2 workers=$3 kind=$4 status=0 line
  shift 4
  # At one worker every run of the race is kept on the same CPU: a core of a shared machine
  # can be slower than the other for minutes, and a run stopped and continued stays where
  # it ran, so unpinned runs could spend the whole race on different cores.
  local pin=()
  if [ "$workers" = 1 ] && [ -n "$race_cpu" ]; then pin=(--cpu="$race_cpu"); fi
  "$turns_binary" "${pin[@]}" "$@" >"$work/output" || status=$?
  while IFS= read -r line; do
    case $line in
      race\ *)
        if [ "$kind" = main ]; then echo "round=$round $line" >>"$work/runs"; fi
        echo "$line" | awk -v round="$round" -v kind="$kind" '{
          for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
          printf "round %s  %-13s %d worker(s)  %-19s %9.3f ms/step (CPU %.3f)", round,
                 f["scene"], f["workers"], f["implementation"], f["median_ns"] / 1e6,
                 f["cpu_median_ns"] / 1e6
          if (kind == "main") printf "  peak %6.1f MiB\n", f["peak_kib"] / 1024
          else printf "  (cost race)\n" }'
        ;;
      phase\ *) if [ "$kind" = main ]; then echo "round=$round $line" >>"$work/phases"; fi ;;
      *) if [ "$round" = 1 ] && [ "$workers" = "$first_workers" ]; then echo "$line"; fi ;;
    esac
  done <"$work/output"
  if [ "$status" -ne 0 ]; then failed+=" $scene/$workers($kind)"; fi
}

# add_run IMPLEMENTATION SAMPLES [ARGS...]: appends to `commands` (after --and when it holds
# one already) the run of $scene at $workers workers by that implementation's runner.
add_run() {
  local implementation=$1 samples=$2 runner=$mink_runner
  shift 2
  case $implementation in box2d_v3*) runner=$v3_runner ;; esac
  if [ ${#commands[@]} -gt 0 ]; then commands+=(--and); fi
  commands+=("$runner" "$scene" --workers="$workers" --implementation="$implementation"
    --sleep="$sleep_mode" --samples="$samples" ${steps:+"--steps=$steps"} "$@")
}

for round in $(seq "$rounds"); do
  for scene in $scenes; do
    steps=$(steps_for "$scene")
    for workers in $workers_list; do
      # The implementations of one scene and worker count take turns of $turn_ms ms.
      commands=()
      for implementation in $implementations; do
        add_run "$implementation" "$work/$scene.$workers.$implementation" --turn-ms="$turn_ms" \
          --profile
      done
      race "$round" "$scene" "$workers" main "${commands[@]}"
      if [ "$cost_race" != on ]; then continue; fi
      # Part 3: each engine on and off, in turns of $cost_turn_steps steps.
      commands=()
      for pair in $cost_pairs; do
        for implementation in "${pair%%:*}" "${pair##*:}"; do
          add_run "$implementation" "$work/cost.$round.$scene.$workers.$implementation" \
            --turn-steps="$cost_turn_steps"
        done
      done
      race "$round" "$scene" "$workers" cost "${commands[@]}"
    done
  done
done
echo "Race against Box2D v3 took $((SECONDS - started)) s"

# column_median COLUMN FILE: the median of the numbers in that space-separated column.
column_median() {
  cut -d' ' -f"$1" "$2" | sort -g | awk '
    { v[NR] = $1 }
    END { printf "%.6f", NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# Medians over the pooled timed steps of every round: wall times (column 1 of the samples)
# into step_v3.csv, CPU times (column 2) into step_v3_cpu.csv.
v3_csv=$results_dir/step_v3.csv
cpu_csv=$results_dir/step_v3_cpu.csv
write_medians() {
  local column=$1 scene workers implementation samples
  echo "case,size,implementation,median_ns"
  for scene in $scenes; do
    for workers in $workers_list; do
      for implementation in $implementations; do
        samples=$work/$scene.$workers.$implementation
        if [ ! -s "$samples" ]; then continue; fi
        printf "%s,%.0f\n" "$scene,$workers,$implementation" "$(column_median "$column" "$samples")"
      done
    done
  done
}
write_medians 1 >"$v3_csv"
write_medians 2 >"$cpu_csv"

memory_csv=$results_dir/step_v3_memory.csv
counts_csv=$results_dir/step_v3_counts.csv
awk -v first_workers="$first_workers" -v scenes="$scenes" \
    -v implementations="$implementations" -v memory="$memory_csv" -v counts="$counts_csv" '
  {
    for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
    if (f["workers"] != first_workers) next
    key = f["scene"] "," f["implementation"]
    if (!(key in peak) || f["peak_kib"] + 0 > peak[key]) peak[key] = f["peak_kib"] + 0
    if (f["round"] == 1) {
      count[key] = f["bodies"] "," f["shapes"] "," f["joints"] "," f["contacts"]
    }
  }
  END {
    ns = split(scenes, s, " ")
    ni = split(implementations, m, " ")
    print "case,implementation,peak_kib" >memory
    print "case,implementation,bodies,shapes,joints,contacts" >counts
    for (i = 1; i <= ns; ++i) {
      for (j = 1; j <= ni; ++j) {
        key = s[i] "," m[j]
        if (key in peak) print key "," peak[key] >memory
        if (key in count) print key "," count[key] >counts
      }
    }
  }' "$work/runs"

# Ours / Box2D v3, one column per setting and worker count. Empty where a side did not run or
# where the two are not the same scene: their shape or joint counts differ (said on stderr; the
# bodies may differ, as a static ground is one body or several).
ratios_csv=$results_dir/step_v3_ratios.csv
# write_ratios MEDIANS_CSV WARN: the ratios of those medians; WARN 1 names the scenes left out.
write_ratios() {
  awk -F, -v workers_list="$workers_list" -v scenes="$scenes" -v warn="$2" '
    FNR == 1 { ++file; next }
    file == 1 { content[$1 "," $2] = $4 "," $5; next }
    { t[$1 "," $2 "," $3] = $4 }
    END {
      nw = split(workers_list, w, " ")
      ns = split(scenes, s, " ")
      no = split("mink_matched mink_defaults", ours, " ")
      header = "case"
      for (j = 1; j <= nw; ++j) {
        for (k = 1; k <= no; ++k) header = header "," ours[k] "_" w[j] "w"
      }
      print header
      for (i = 1; i <= ns; ++i) {
        row = s[i]
        theirs = content[s[i] ",box2d_v3"]
        for (j = 1; j <= nw; ++j) {
          v3 = t[s[i] "," w[j] ",box2d_v3"]
          for (k = 1; k <= no; ++k) {
            mine = t[s[i] "," w[j] "," ours[k]]
            same = content[s[i] "," ours[k]] == theirs
            if (warn && mine != "" && v3 != "" && !same && !((s[i] "," ours[k]) in said)) {
              said[s[i] "," ours[k]] = 1
              printf "run_step.sh: %s: no ratio for %s: its shapes,joints %s are not" \
                     " Box2D v3%cs %s (not the same scene)\n", s[i], ours[k],
                     content[s[i] "," ours[k]], 39, theirs >"/dev/stderr"
            }
            row = row "," (v3 != "" && mine != "" && same ? sprintf("%.3f", mine / v3) : "")
          }
        }
        print row
      }
    }' "$counts_csv" "$1"
}
write_ratios "$v3_csv" 1 >"$ratios_csv"

# The mean time per step of each phase each engine reports, over the rounds.
phases_csv=$results_dir/step_v3_phases.csv
awk -v scenes="$scenes" -v workers_list="$workers_list" -v implementations="$implementations" '
  {
    for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
    key = f["scene"] "," f["workers"] "," f["implementation"]
    if (!((key "," f["name"]) in sum)) names[key] = names[key] " " f["name"]
    sum[key "," f["name"]] += f["ms"]
    ++n[key "," f["name"]]
  }
  END {
    print "case,workers,implementation,phase,mean_ms"
    ns = split(scenes, s, " ")
    nw = split(workers_list, w, " ")
    ni = split(implementations, m, " ")
    for (i = 1; i <= ns; ++i) for (j = 1; j <= nw; ++j) for (k = 1; k <= ni; ++k) {
      key = s[i] "," w[j] "," m[k]
      np = split(names[key], p, " ")
      for (q = 1; q <= np; ++q) printf "%s,%s,%.4f\n", key, p[q], sum[key "," p[q]] / n[key "," p[q]]
    }
  }' "$work/phases" >"$phases_csv"

# What continuous collision costs (part 3): step i of each on run against step i of its off
# twin, round by round. paired_cost SCENE WORKERS ON OFF prints on_ns,off_ns,cost,total_cost
# (empty fields when the pair did not run).
paired_cost() {
  local scene=$1 workers=$2 on=$3 off=$4 files=() round on_file off_file
  for round in $(seq "$rounds"); do
    on_file=$work/cost.$round.$scene.$workers.$on
    off_file=$work/cost.$round.$scene.$workers.$off
    if [ -s "$on_file" ] && [ -s "$off_file" ]; then files+=("$on_file" "$off_file"); fi
  done
  if [ ${#files[@]} -eq 0 ]; then
    echo ",,,"
    return
  fi
  # Sample lines: wall_ns cpu_ns step. Out: on / off, on_ns, off_ns for each step both timed.
  awk 'FNR == 1 { ++file }
       file % 2 == 1 { on[file, $3] = $1; next }
       ((file - 1, $3) in on) { print on[file - 1, $3] / $1, on[file - 1, $3], $1 }' \
    "${files[@]}" >"$work/paired"
  local column medians=()
  for column in 1 2 3; do medians+=("$(column_median "$column" "$work/paired")"); done
  awk -v ratio="${medians[0]}" -v on="${medians[1]}" -v off="${medians[2]}" '
    { sum_on += $2; sum_off += $3 }
    END { printf "%.0f,%.0f,%.4f,%.4f\n", on, off, ratio - 1, sum_on / sum_off - 1 }' \
    "$work/paired"
}
continuous_csv=$results_dir/step_v3_continuous.csv
if [ "$cost_race" = on ]; then
  {
    echo "case,workers,on_ns,off_ns,cost,total_cost,phase_share,v3_on_ns,v3_off_ns,v3_cost,v3_total_cost"
    for scene in $scenes; do
      for workers in $workers_list; do
        ours=$(paired_cost "$scene" "$workers" mink_matched mink_matched_no_ccd)
        theirs=$(paired_cost "$scene" "$workers" box2d_v3 box2d_v3_no_ccd)
        if [ "$ours" = ",,," ]; then continue; fi
        # The continuous phase's share of the matched step, within each run of part 2.
        share=$(awk -F, -v key="$scene,$workers,mink_matched" '
          $1 "," $2 "," $3 == key && $4 == "continuous" { phase = $5 }
          $1 "," $2 "," $3 == key && $4 == "step" { whole = $5 }
          END { if (whole > 0) printf "%.4f", phase / whole }' "$phases_csv")
        echo "$scene,$workers,${ours%,*,*},${ours#*,*,},$share,$theirs"
      done
    done
  } >"$continuous_csv"
fi

echo
echo "Ours / Box2D v3 (median step time; below 1: ours is faster), $ratios_csv:"
column -s, -t "$ratios_csv"
echo
echo "The same for CPU time (at 1 worker the time on a core of its own; $cpu_csv):"
write_ratios "$cpu_csv" 0 | column -s, -t
if [ "$cost_race" = on ]; then
  echo
  echo "What continuous collision costs (part 3: the median over paired steps of on / off - 1;" \
    "total_cost: their summed times; phase_share: the continuous phase's share of the step in" \
    "mink_matched), $continuous_csv:"
  column -s, -t "$continuous_csv"
fi
echo
echo "Peak memory (KiB, $first_workers worker(s)), $memory_csv:"
column -s, -t "$memory_csv"
echo
echo "Counts at the end of a run, $counts_csv:"
column -s, -t "$counts_csv"

png=$results_dir/step_v3.png
if ! awk -F, 'NR > 1 { for (i = 2; i <= NF; ++i) if ($i != "") found = 1 } END { exit !found }' \
  "$ratios_csv"; then
  echo "run_step.sh: no ratios to plot; $png not drawn"
elif command -v gnuplot >/dev/null; then
  terminal=png
  if gnuplot -e 'set terminal pngcairo' >/dev/null 2>&1; then terminal=pngcairo; fi
  gnuplot -e "csv='$ratios_csv'; png='$png'; terminal='$terminal'" "$bench_dir/plot_step_v3.gp"
  echo "Wrote $v3_csv, $png"
else
  echo "run_step.sh: gnuplot not found (apt install gnuplot-nox); $png not drawn" >&2
fi
if [ -n "$failed" ]; then
  echo "run_step.sh: these runs failed (their output is above):$failed" >&2
  exit 1
fi
