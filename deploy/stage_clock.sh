# Sourced by deploy/test.sh: times each stage of a run and, when the run ends (passed or not),
# prints a table of the stages with their minutes and the ten slowest tests of every CTest tree
# the run used, so that where CI's minutes go is read from its own log, not guessed.
#   stage NAME COMMAND...   runs COMMAND as stage NAME; its status is the command's.
#   stage_tree DIR          names a CTest tree whose test times the table lists.
_stage_names=()
_stage_secs=()
_stage_status=()
_stage_trees=()
_stage_run_start=$SECONDS

stage() {
  local name=$1 start=$SECONDS rc=0
  shift
  "$@" || rc=$?
  _stage_names+=("$name")
  _stage_secs+=($((SECONDS - start)))
  _stage_status+=("$rc")
  return "$rc"
}

stage_tree() { _stage_trees+=("$1"); }

_stage_report() {
  local i total=$((SECONDS - _stage_run_start))
  {
    echo "================================ stage times ================================"
    printf '%-44s %8s %8s\n' stage minutes status
    for i in "${!_stage_names[@]}"; do
      awk -v n="${_stage_names[$i]}" -v s="${_stage_secs[$i]}" -v r="${_stage_status[$i]}" \
        'BEGIN{printf "%-44s %8.1f %8s\n", n, s / 60, r}'
    done
    awk -v s="$total" 'BEGIN{printf "%-44s %8.1f\n", "total", s / 60}'
    # CTestCostData.txt: "name runs average-seconds" per test of the tree's last runs.
    local lines=""
    for tree in "${_stage_trees[@]}"; do
      local cost=$tree/Testing/Temporary/CTestCostData.txt
      [[ -f $cost ]] || continue
      lines+=$(awk -v t="$tree" '/^---/{exit} NF==3{printf "%s %s:%s\n", $3, t, $1}' "$cost")$'\n'
    done
    if [[ -n $lines ]]; then
      echo "--------------------------- ten slowest tests (s) ---------------------------"
      printf '%s' "$lines" | sort -rn | head -10 | awk '{printf "%8.1f  %s\n", $1, $2}'
    fi
    echo "============================================================================="
  } >&2
}
trap _stage_report EXIT
