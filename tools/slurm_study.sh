#!/usr/bin/env bash
# A study on a Slurm cluster: one array task per shard, then the merge and the report.
#
#   tools/slurm_study.sh --shards N --out DIR [--collido PATH] [--sbatch OPTION]... [--wait] \
#     -- STUDY ARGUMENTS (scenes, --sweep, --surfaces, --frep, ...)
#
# Submits DIR/study.sbatch, an sbatch job array of N tasks: task I runs
#   collido study ARGS --shard I/N --out DIR/shard-I --oracle-store DIR/oracle --resume --quiet
# (so a task that is run again resumes its shard), and, once every task has ended whatever its
# end (afterany), DIR/merge.sbatch: `collido merge --out DIR/all DIR/shard-*`, then
# `collido report DIR/all`. The shards share one oracle store: a scene's exact answers computed by
# one shard are read by the others that come to it later (on a filesystem every node sees).
# `collido` is the installed one (on PATH) unless --collido names another. --sbatch passes an
# option to both submissions (e.g. --sbatch --partition=long --sbatch --time=04:00:00).
# --wait returns only when the merge job has ended, with its exit status.
# Prints the two job ids. Logs: DIR/logs/.
set -euo pipefail
shards=""
out=""
collido=""
wait_for_merge=false
sbatch_options=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --shards) shards="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --collido) collido="$2"; shift 2 ;;
    --sbatch) sbatch_options+=("$2"); shift 2 ;;
    --wait) wait_for_merge=true; shift ;;
    --) shift; break ;;
    *) echo "error: unknown argument '$1' (see the header of $0)" >&2; exit 2 ;;
  esac
done
study_arguments=("$@")
if [[ ! $shards =~ ^[1-9][0-9]*$ ]]; then
  echo "error: --shards needs a positive count, got '${shards}'" >&2
  exit 2
fi
if [[ -z $out ]]; then
  echo "error: --out DIR is required" >&2
  exit 2
fi
if [[ ${#study_arguments[@]} -eq 0 ]]; then
  echo "error: no study arguments after --" >&2
  exit 2
fi
if [[ -z $collido ]]; then
  collido=$(command -v collido || true)
  if [[ -z $collido ]]; then
    echo "error: collido is not on PATH; install it (README: Use it from your project) or give" \
         "--collido PATH" >&2
    exit 2
  fi
fi
collido=$(realpath "$collido")
command -v sbatch > /dev/null || { echo "error: sbatch not found (not a Slurm submit host?)" >&2; exit 2; }
mkdir -p "$out/logs"
out=$(realpath "$out")

# The tasks run in the submitting folder (relative scene paths keep their meaning); every path
# and argument is quoted into the scripts as given.
quoted_arguments=$(printf ' %q' "${study_arguments[@]}")
q_out=$(printf '%q' "$out")
q_collido=$(printf '%q' "$collido")
cat > "$out/study.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=collido-study
#SBATCH --array=0-$((shards - 1))
#SBATCH --cpus-per-task=1
#SBATCH --chdir=$(printf '%q' "$PWD")
#SBATCH --output=$q_out/logs/shard-%a.log
set -euo pipefail
$q_collido study${quoted_arguments} \\
  --shard "\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT" \\
  --out $q_out/shard-"\$SLURM_ARRAY_TASK_ID" --oracle-store $q_out/oracle --resume --quiet
SBATCH
cat > "$out/merge.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=collido-merge
#SBATCH --cpus-per-task=1
#SBATCH --output=$q_out/logs/merge.log
set -euo pipefail
shopt -s nullglob
shard_folders=($q_out/shard-*)
$q_collido merge --replace --out $q_out/all "\${shard_folders[@]}"
$q_collido report $q_out/all
SBATCH

study_job=$(sbatch --parsable "${sbatch_options[@]}" "$out/study.sbatch")
study_job=${study_job%%;*}
merge_options=(--parsable --dependency="afterany:$study_job")
if $wait_for_merge; then merge_options+=(--wait); fi
echo "study job $study_job: $shards shards, logs in $out/logs/"
merge_status=0
merge_job=$(sbatch "${merge_options[@]}" "${sbatch_options[@]}" "$out/merge.sbatch") ||
  merge_status=$?
echo "merge job ${merge_job%%;*}: $out/all/{table.txt,report.html} once it ends"
exit "$merge_status"
