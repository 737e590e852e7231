#!/usr/bin/env bash
# Installs what is needed from Debian, builds a Release tree with tests, runs every test
# through CTest. Exits non-zero on any failure. .ci/run calls exactly this.
# OCEAN_SANITIZE=1 adds the sanitizer runs (SECURITY.md): every test under ASan + UBSan
# (build-asan), and the threaded server / client / loadtest tests under TSan (build-tsan).
# OCEAN_SANITIZE=1 OCEAN_SANITIZE_ONLY=asan (or tsan) runs just that sanitizer run, without the
# Release one.
# OCEAN_CONTAINER=1 adds the container stage after the Release tests (deploy/container_test.sh):
# podman builds deploy/Dockerfile, runs it and load-tests it, then kube play runs 2 replicas of
# deploy/k8s and clients fail over between them. It fails the run when the container does not
# work; it is skipped, with a banner, only when podman cannot create any container on the machine.
#
# Where the time goes (deploy/stage_clock.sh prints the table at the end): every tree is a unity
# build (deploy/build.sh), the sanitizer trees are compiled by clang (a third faster than g++ with
# the same sanitizers), CTest runs tests side by side within their CPU budgets (tests/CMakeLists:
# waiting tests share the cores, computing ones do not), and the TSan tree compiles at the lowest
# priority while the ASan tests run, on the CPU they leave idle (they assert no timing).
set -euo pipefail
cd "$(dirname "$0")/.."
source deploy/stage_clock.sh
stage "packages" ./deploy/install-deps.sh
# Tests side by side: CTest keeps to each test's CPU budget (ctest-resources.json); this bounds
# only how many wait at once.
jobs=$((4 * $(nproc)))
only=${OCEAN_SANITIZE_ONLY:-}
if [[ -z "$only" || "${OCEAN_SANITIZE:-}" != 1 ]]; then
  # With the browser viewer (Emscripten) and its test in headless Chromium (tests/web).
  build_dir=${OCEAN_BUILD_DIR:-build}
  stage_tree "$build_dir"
  stage "Release: configure + build (web included)" ./deploy/build.sh -DOCEAN_BUILD_WEB=ON
  stage "Release: tests" ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" --timeout 600
  if [[ "${OCEAN_CONTAINER:-}" == 1 ]]; then
    # After CTest, never beside it: the image build takes both cores, and the load tests in CTest
    # assert on-time shares.
    rc=0
    OCEAN_BUILD_DIR=$build_dir stage "container stage" ./deploy/container_test.sh || rc=$?
    if ((rc == 77)); then
      echo "=================================================================================" >&2
      echo "test.sh: CONTAINER STAGE SKIPPED: podman cannot create a container here (see above)" >&2
      echo "=================================================================================" >&2
    elif ((rc != 0)); then
      echo "test.sh: the container stage failed (deploy/container_test.sh, status $rc)" >&2
      exit "$rc"
    fi
  fi
fi

if [[ "${OCEAN_SANITIZE:-}" != 1 ]]; then
  exit 0
fi
# Findings stop the test: UBSan halts (the build also passes -fno-sanitize-recover=all); LSan may
# ignore only Mesa/LLVM-internal leaks (tests/sanitizers/lsan.supp, never ours); the GL test
# processes skip the leak check (tests/sanitizers/no_leak_check.cpp says why).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:detect_stack_use_after_return=1:strict_init_order=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}

# -O1 and line tables only (-g1: enough for every report's stack): at -O2 -g the ASan tree took 34
# of a clean CI run's 73 minutes to compile on 2 cores (2026-11-27).
sanitizer_build() {
  CC=clang CXX=clang++ OCEAN_BUILD_DIR=$1 ./deploy/build.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "${@:2}"
}
# Only the threaded parts: the server (tick loop, sessions), the client connection, the load test's
# pieces and the replica tests (their ocean-server processes run under TSan too). Not the
# load-test scenarios or tests/faults: they assert on-time shares that a 5-15x slower TSan build
# cannot meet (a full TSan run of them on 2026-11-21 reported no race, only missed deadlines).
tsan_args=(-DOCEAN_SANITIZE=thread -DOCEAN_BUILD_CLIENT=OFF
  "-DOCEAN_DIRS=sim;protocol;protocol/codec;protocol/scene_wire;server/net;server;client/net;client/loadtest;tests;tests/support;tests/server;tests/client_net;tests/loadtest;tests/replica")
tsan_tests=(-R 'server|client_net|loadtest|replica' -E 'loadtest_scenario')

if [[ -z "$only" || "$only" == asan ]]; then
  stage_tree build-asan
  stage "ASan + UBSan: configure + build" sanitizer_build build-asan -DOCEAN_SANITIZE=address,undefined
  if [[ -z "$only" ]]; then
    stage_background "TSan: configure + build" build-tsan.log sanitizer_build build-tsan "${tsan_args[@]}"
  fi
  stage "ASan + UBSan: tests" ctest --test-dir build-asan --output-on-failure -j"$jobs" --timeout 1800
fi
if [[ -z "$only" || "$only" == tsan ]]; then
  stage_tree build-tsan
  if [[ -z "$only" ]]; then
    stage_wait "TSan: configure + build"
  else
    stage "TSan: configure + build" sanitizer_build build-tsan "${tsan_args[@]}"
  fi
  stage "TSan: tests" ctest --test-dir build-tsan --output-on-failure -j"$jobs" --timeout 1800 "${tsan_tests[@]}"
fi
