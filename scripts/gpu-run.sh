#!/usr/bin/env bash
# Runs on a lent GPU machine, from the project's root, after
# scripts/gpu-bundle.sh: finds a Vulkan driver manifest the loader accepts,
# measures (bench, denoise of the armadillo at 128/256/512 beside OpenVDB,
# a 48-frame morph at 256, the 12 shared meshes in one jobs file, a
# baseline build beside this one where gpu-bundle.sh was given one), then runs
# every test program with the validation layer on, in shards, for at most
# GPU_TEST_SECONDS (default 150). Everything goes into $OUT/results.tgz,
# written again after each phase so that a run cut short still returns
# what it did.
#
# Headless, NVIDIA's own manifest (libGLX_nvidia.so.0) does not start
# ("Could not get 'vkCreateInstance' via 'vk_icdGetInstanceProcAddr'"): a
# manifest naming libEGL_nvidia.so.0 does, and is tried first.
set -u
results=/tmp/gpu-results
rm -rf "$results" && mkdir -p "$results"
save() { (cd "$results" && tar czf "$OUT/results.tgz" .); }
# GPU_PHASES: which phases run (default all but probe): figures (bench,
# the armadillo's denoises and the morph at 256, with their traces), probe
# (the driver's start, an open scan's distances, a band at 640 traced),
# choices (every shared mesh with --sdf auto and cpu in fresh processes at
# 128 and 256, the jobs file with --sdf cpu, a morph's frames with
# --extract auto and cpu: what the auto rules are set by),
# scale (bench-scale.sh beside OpenVDB), jobs (the 12 meshes), baseline
# (this build and the baseline alternately), tests.
wanted() { [[ " ${GPU_PHASES:-figures scale jobs baseline tests} " == *" $1 "* ]]; }
trap save EXIT
root=$PWD
source .gpu/prepare.sh 2>"$results/prepare.log"

# The driver.
mkdir -p /tmp/icd
echo '{"file_format_version":"1.0.1","ICD":{"library_path":"libEGL_nvidia.so.0","api_version":"1.4.312"}}' >/tmp/icd/egl.json
driver=""
for manifest in /tmp/icd/egl.json $(ls /usr/local/nvidia/share/vulkan/icd.d/*.json /usr/share/vulkan/icd.d/*.json 2>/dev/null); do
  if VK_DRIVER_FILES=$manifest .gpu/bin/lbmshape info >>"$results/driver.log" 2>&1; then driver=$manifest; break; fi
done
echo "driver manifest: ${driver:-none works}" >>"$results/driver.log"
save
[[ -n $driver ]] || exit 1
export VK_DRIVER_FILES=$driver VK_ICD_FILENAMES=$driver

# The absolute paths the tests were built with: /work/main and /work/shared.
mkdir -p "$root/../shared" && tar xJf .gpu/assets.tar.xz -C "$root/../shared"
[[ $root == /work/main ]] || { mkdir -p /work && rm -rf /work/main && ln -s "$root" /work/main; }
[[ -e /work/shared ]] || ln -s "$(cd "$root/../shared" && pwd)" /work/shared
[[ -f .gpu/tests.tar.xz ]] && tar xJf .gpu/tests.tar.xz -C .gpu  # packed by gpu-bundle.sh
mkdir -p build/tests scripts && cp .gpu/bin/lbmshape build/ && cp .gpu/tests/* build/tests/
cp .gpu/bench-scale.sh .gpu/make-sphere.py scripts/ 2>/dev/null
if [[ -f .gpu/peer.tar.xz ]]; then
  tar xJf .gpu/peer.tar.xz -C .gpu
  export VDB_PEER=$root/.gpu/peer/vdb_peer LD_LIBRARY_PATH=$root/.gpu/peer/lib:$LD_LIBRARY_PATH
fi
assets=/work/shared/assets

python3 scripts/make-sphere.py /tmp/sphere.obj
if wanted probe; then
  { for run in 1 2 3; do /usr/bin/time -f "lbmshape info: %e s" lbmshape info >/dev/null; done
    for sdf in device cpu device cpu; do
      lbmshape -v denoise $assets/bunny_scan.obj /tmp/scan.glb --res 128 --sdf $sdf 2>&1 | grep -E "band distances|^lbmshape: (sdf|lbm|total) "
    done
    LBMSHAPE_DEVICE_TRACE=1 timeout 60 lbmshape -v denoise /tmp/sphere.obj /tmp/s640.glb --res 640 --sdf cpu 2>&1 | grep -v "\.\.\. [0-9.]* s$"
  } >"$results/probe.log" 2>&1
  save
fi
if wanted choices; then
  { lbmshape -q denoise $assets/bunny.obj /tmp/warm.glb --res 64   # the pipelines compiled once
    for run in 1 2 3; do /usr/bin/time -f "lbmshape --version: %e s" lbmshape --version >/dev/null; done
    for res in 128 256; do
      for m in $assets/*.obj; do
        for sdf in auto cpu auto cpu; do
          /usr/bin/time -f "$(basename $m) $res --sdf $sdf: %e s, %M KB" timeout 30 lbmshape -v denoise $m /tmp/choice.glb --res $res --sdf $sdf 2>&1 |
            grep -E "band distances|^lbmshape: (read|sdf|lbm) |wrote .* in |closed in| s, "
        done
      done
    done
  } >"$results/choices-sdf.log" 2>&1
  save
  python3 - "$assets" >/tmp/jobs.json <<'PY'
import json, os, sys
print(json.dumps([{"command": "denoise", "input": f"{sys.argv[1]}/{m}", "output": f"/tmp/jobs-{m[:-4]}.glb", "res": 128}
                  for m in sorted(os.listdir(sys.argv[1])) if m.endswith(".obj")]))
PY
  { for run in 1 2 3; do
      for sdf in auto cpu; do
        rm -rf /tmp/jobs-cache
        XDG_CACHE_HOME=/tmp/jobs-cache /usr/bin/time -f "jobs file --sdf $sdf: %e s, %M KB" timeout 60 lbmshape -q --sdf $sdf run /tmp/jobs.json >/dev/null
      done
    done
    for run in 1 2 3; do
      for extract in auto cpu; do
        /usr/bin/time -f "morph 256 --extract $extract: %e s, %M KB" timeout 60 lbmshape -v morph /tmp/sphere.obj $assets/armadillo.obj /tmp/m256 --res 256 --align none --force --extract $extract 2>&1 |
          grep -E "band distances|^lbmshape: [a-z]+ +[0-9.]+ ms|waited|animation|closed in| s, "
      done
    done
  } >"$results/choices-jobs-morph.log" 2>&1
  save
fi
# Figures, on a quiet machine.
if wanted figures; then
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv; nproc
  timeout 90 lbmshape bench --size 256,256,256 --json -q; echo
  timeout 90 lbmshape bench --band --size 512,512,512 --json -q; echo; } >"$results/bench.log" 2>&1
for res in 128 256 512; do
  timeout 30 lbmshape -v denoise $assets/armadillo.obj /tmp/armadillo$res.glb --res $res --json \
    >"$results/denoise$res.json" 2>"$results/denoise$res.err"
  timeout 30 lbmshape -v denoise $assets/armadillo.obj /tmp/armadillo$res.glb --res $res --json --isotropic \
    >"$results/denoise$res-isotropic.json" 2>"$results/denoise$res-isotropic.err"
  # The distances on the host's cores, against the device's (--sdf auto on a GPU) above.
  timeout 30 lbmshape -v denoise $assets/armadillo.obj /tmp/armadillo$res.glb --res $res --json --sdf cpu \
    >"$results/denoise$res-sdf-cpu.json" 2>"$results/denoise$res-sdf-cpu.err"
done
# Every compute submission of a denoise at 512 and of the morph at 256,
# beside the -v stage lines: where the device waits for the host.
LBMSHAPE_DEVICE_TRACE=1 timeout 30 lbmshape -v denoise $assets/armadillo.obj /tmp/trace512.glb --res 512 \
  2>"$results/trace-denoise512.err" >/dev/null
LBMSHAPE_DEVICE_TRACE=1 timeout 60 lbmshape -v morph /tmp/sphere.obj $assets/armadillo.obj /tmp/trace-morph \
  --res 256 --align none --force 2>"$results/trace-morph256.err" >/dev/null
timeout 60 lbmshape -v morph /tmp/sphere.obj $assets/armadillo.obj /tmp/morph256 --res 256 --align none --force --json \
  >"$results/morph256.json" 2>"$results/morph256.err"
# The frames read back as whole fields, against the surfaces' pieces
# listed on the device (--extract auto on a GPU) above.
timeout 60 lbmshape -v morph /tmp/sphere.obj $assets/armadillo.obj /tmp/morph256c --res 256 --align none --force --json \
  --extract cpu >"$results/morph256-extract-cpu.json" 2>"$results/morph256-extract-cpu.err"
save
fi
if wanted scale; then
  timeout 120 scripts/bench-scale.sh $assets/armadillo.obj 3 128 256 512 >"$results/scale.log" 2>&1
fi
if wanted jobs; then
python3 - "$assets" >/tmp/jobs.json <<'PY'
import json, os, sys
print(json.dumps([{"command": "denoise", "input": f"{sys.argv[1]}/{m}", "output": f"/tmp/jobs-{m[:-4]}.glb", "res": 128}
                  for m in sorted(os.listdir(sys.argv[1])) if m.endswith(".obj")]))
PY
{ for run in 1 2 3; do
    rm -rf /tmp/jobs-cache
    XDG_CACHE_HOME=/tmp/jobs-cache /usr/bin/time -f "jobs file: %e s, %M KB" timeout 60 lbmshape -q run /tmp/jobs.json --json >"$results/jobs$run.json"
  done
  if [[ -n ${VDB_PEER:-} ]]; then
    for run in 1 2 3; do
      /usr/bin/time -f "OpenVDB, 12 processes: %e s" bash -c \
        "for m in $assets/*.obj; do $VDB_PEER denoise \$m /tmp/vdb.obj --res 128 --iters 3 --filter meancurv --threads $(nproc) >/dev/null 2>&1; done"
    done
  fi; } >"$results/jobs.log" 2>&1
fi
save
# Whole-process times of denoises and of the morph as a user runs it (no
# --json), this build and the baseline alternately: the baseline is a binary
# (BASELINE= for gpu-bundle.sh) or this one in another environment
# (GPU_AB_ENV="NAME=value ...": a setting's effect on the same build).
if wanted baseline; then
  builds=(lbmshape)
  [[ -x .gpu/bin/lbmshape-baseline ]] && builds+=(lbmshape-baseline)
  [[ -n ${GPU_AB_ENV:-} ]] && builds+=("env $GPU_AB_ENV lbmshape")
  { cat /sys/kernel/mm/transparent_hugepage/enabled 2>&1 | sed 's/^/transparent_hugepage: /'
    # What a frame's durable write costs there: a 3.6 MB file and its folder synced.
    python3 -c "
import os, time, statistics
t = []
for k in range(10):
    s = time.perf_counter()
    with open(f'/tmp/sync{k}', 'wb') as f: f.write(os.urandom(3600000)); f.flush(); os.fsync(f.fileno())
    d = os.open('/tmp', os.O_RDONLY); os.fsync(d); os.close(d)
    t.append((time.perf_counter() - s) * 1000)
print('a 3.6 MB file written and synced with its folder: median %.1f ms (%.1f-%.1f)' % (statistics.median(t), min(t), max(t)))"
    for run in $(seq "${GPU_BASELINE_RUNS:-2}"); do
      for b in "${builds[@]}"; do
        for res in 128 256 512; do
          /usr/bin/time -f "$b denoise $res: %e s, %M KB" timeout 30 $b -v denoise $assets/armadillo.obj /tmp/d$res.glb --res $res 2>&1 |
            grep -E "band distances|^lbmshape: (sdf|lbm|extract) |closed in| s, "
        done
        /usr/bin/time -f "$b morph 256: %e s, %M KB" timeout 60 $b -v morph /tmp/sphere.obj $assets/armadillo.obj /tmp/m256 --res 256 --align none --force 2>&1 |
          grep -E "band distances|^lbmshape: [a-z]+ +[0-9.]+ ms|waited|closed in| s, "
      done
    done; } >"$results/baseline.log" 2>&1
  save
fi

# The suite, validation on (each program's main sets it), GPU_SHARDS shards
# a program (default 8: with 4, cli_tests' first shard did not finish in
# 150 s on the H100, 2026-11-28); GPU_PROGRAMS names some programs instead
# of all (GPU_PROGRAMS=cli_tests GPU_SHARDS=16: one program on every core).
wanted tests || exit 0
cd build/tests
shards=${GPU_SHARDS:-8}
ls ${GPU_PROGRAMS:-*_tests} | while read -r program; do for shard in $(seq 0 $((shards - 1))); do echo "$program $shard"; done; done |
  timeout -s KILL "${GPU_TEST_SECONDS:-150}" xargs -P "$(nproc)" -n 2 sh -c \
    'GTEST_TOTAL_SHARDS='"$shards"' GTEST_SHARD_INDEX=$1 ./$0 --gtest_brief=1 >'"$results"'/test-$0-$1.log 2>&1; echo "$0 $1 exit $?"' \
    >"$results/tests.summary" 2>&1
pkill -f '_tests --gtest_brief' 2>/dev/null
grep -h '^\[  FAILED  \]' "$results"/test-*.log | sort -u >"$results/tests.failed"
