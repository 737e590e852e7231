# Sourced by deploy/test.sh: times each stage of a run and, when the run ends (passed or not),
# prints a table of the stages with their minutes and the ten slowest tests of every CTest tree
# the run used, so that where CI's minutes go is read from its own log, not guessed.
#   stage NAME COMMAND...             runs COMMAND as stage NAME; its status is the command's.
#   stage_background NAME LOG COMMAND...
#                                     starts COMMAND at the lowest CPU priority (nice 19), its
#                                     output in LOG, beside the stages that follow: it takes only
#                                     the CPU they leave idle.
#   stage_wait NAME                   waits for that stage; on failure prints the end of its LOG.
#   stage_tree DIR                    names a CTest tree whose test times the table lists.
_stage_names=()
_stage_secs=()
_stage_status=()
_stage_trees=()
_stage_run_start=$SECONDS
_stage_bg_dir=$(mktemp -d)
declare -A _stage_bg_pid _stage_bg_log

_stage_record() {
  _stage_names+=("$1")
  _stage_secs+=("$2")
  _stage_status+=("$3")
}

stage() {
  local name=$1 start=$SECONDS rc=0
  shift
  "$@" || rc=$?
  _stage_record "$name" $((SECONDS - start)) "$rc"
  return "$rc"
}

stage_background() {
  local name=$1 log=$2
  shift 2
  (
    start=$SECONDS
    rc=0
    renice -n 19 -p "$BASHPID" >/dev/null  # not nice(1): COMMAND may be a shell function
    "$@" >"$log" 2>&1 || rc=$?
    echo "$((SECONDS - start)) $rc" >"$_stage_bg_dir/${name//[^A-Za-z0-9]/_}"
  ) &
  _stage_bg_pid[$name]=$!
  _stage_bg_log[$name]=$log
}

stage_wait() {
  local name=$1 start=$SECONDS secs rc
  wait "${_stage_bg_pid[$name]}" || true
  read -r secs rc <"$_stage_bg_dir/${name//[^A-Za-z0-9]/_}" || { secs=0; rc=1; }
  _stage_record "$name (beside the above, nice 19)" "$secs" "$rc"
  _stage_record "  waited for it" $((SECONDS - start)) 0
  if ((rc != 0)); then
    echo "stage '$name' failed (status $rc); the end of ${_stage_bg_log[$name]}:" >&2
    tail -n 60 "${_stage_bg_log[$name]}" >&2
  fi
  return "$rc"
}

stage_tree() { _stage_trees+=("$1"); }

# The run's status is kept: under set -e -o pipefail a failing command in the report (sort killed
# by SIGPIPE when head has its ten lines) would otherwise replace it (CI once ended 141, not 8).
_stage_report() {
  local rc=$? i total=$((SECONDS - _stage_run_start))
  set +e +o pipefail
  {
    echo
    echo "================================ stage times ================================"
    printf '%-60s %8s %6s\n' stage minutes status
    for i in "${!_stage_names[@]}"; do
      awk -v n="${_stage_names[$i]}" -v s="${_stage_secs[$i]}" -v r="${_stage_status[$i]}" \
        'BEGIN{printf "%-60s %8.1f %6s\n", n, s / 60, r}'
    done
    awk -v s="$total" 'BEGIN{printf "%-60s %8.1f\n", "total", s / 60}'
    # CTestCostData.txt: "name runs average-seconds" per test of the tree's last runs.
    local lines=""
    for tree in "${_stage_trees[@]}"; do
      local cost=$tree/Testing/Temporary/CTestCostData.txt
      [[ -f $cost ]] || continue
      # Names hold spaces: the last two fields are the runs and the seconds.
      lines+=$(awk -v t="$tree" '/^---/{exit} NF>=3{s=$NF; NF-=2; printf "%s %s: %s\n", s, t, $0}' "$cost")$'\n'
    done
    if [[ -n $lines ]]; then
      echo "--------------------------- ten slowest tests (s) ---------------------------"
      printf '%s' "$lines" | sort -rn | awk 'NR <= 10 {s=$1; $1=""; printf "%8.1f %s\n", s, $0}'
    fi
    echo "============================================================================="
  } >&2
  rm -rf "$_stage_bg_dir"
  exit "$rc"
}
trap _stage_report EXIT
