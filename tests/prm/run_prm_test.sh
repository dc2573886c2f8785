#!/bin/bash
# Regression run of the dpana executable on one parameter file.
#
#   run_prm_test.sh DPANA NAME.prm WORKDIR
#
# Runs DPANA NAME.prm in a fresh WORKDIR (emptied first; NAME.prm and, if
# present, the files of the folder NAME.files/ are copied into it). Then:
#
# - if NAME.error exists (a bad-input test): dpana must exit with a non-zero
#   status, write exactly one line to stderr, that line must contain the
#   text of NAME.error (its first line, as a fixed string), and WORKDIR must
#   hold nothing but what was copied there and the captured stdout/stderr:
#   no output directory may be left behind;
# - otherwise: dpana must succeed, and every file under NAME.expected/ must
#   match the file of the same relative path under WORKDIR, compared with
#   numdiff at relative tolerance 1e-6 and absolute tolerance 1e-9 (numbers
#   are split at whitespace and at the JSON punctuation , [ ] { } : "); a
#   JSON file is compared without its "timings", "peak_memory_mb" and
#   "machine".
#
# See tests/prm/README.md.
set -u

if [ $# -ne 3 ]; then
  echo "usage: $0 DPANA NAME.prm WORKDIR" >&2
  exit 2
fi
dpana=$1
prm=$(readlink -f "$2")
workdir=$3
name=$(basename "$prm" .prm)
srcdir=$(dirname "$prm")

rm -rf "$workdir"
mkdir -p "$workdir"
cp "$prm" "$workdir/"
if [ -d "$srcdir/$name.files" ]; then
  cp -r "$srcdir/$name.files/." "$workdir/"
fi
before=$(cd "$workdir" && ls -A | sort)

cd "$workdir" || exit 2
"$dpana" "$name.prm" > stdout.txt 2> stderr.txt
status=$?
after=$(ls -A | grep -v -x -e stdout.txt -e stderr.txt | sort)

if [ -f "$srcdir/$name.error" ]; then
  expected=$(head -n 1 "$srcdir/$name.error")
  failed=0
  if [ $status -eq 0 ]; then
    echo "FAIL: dpana succeeded, expected an error containing: $expected"
    failed=1
  fi
  lines=$(wc -l < stderr.txt)
  if [ "$lines" -ne 1 ]; then
    echo "FAIL: stderr has $lines lines, expected exactly one:"
    cat stderr.txt
    failed=1
  fi
  if ! grep -q -F -- "$expected" stderr.txt; then
    echo "FAIL: stderr does not contain: $expected"
    echo "stderr: $(cat stderr.txt)"
    failed=1
  fi
  if [ "$before" != "$after" ]; then
    echo "FAIL: the run left files behind:"
    comm -13 <(echo "$before") <(echo "$after")
    failed=1
  fi
  [ $failed -eq 0 ] && echo "OK: $(cat stderr.txt)"
  exit $failed
fi

if [ $status -ne 0 ]; then
  echo "FAIL: dpana exited with status $status"
  cat stderr.txt
  exit 1
fi
if [ ! -d "$srcdir/$name.expected" ]; then
  echo "FAIL: neither $name.error nor $name.expected/ exists"
  exit 1
fi
# A JSON file is compared without its "timings", "peak_memory_mb",
# "memory_estimate_mb" (which holds the resident memory of the run) and
# "machine" (the processor and BLAS kernels of the run), which change from
# run to run and machine to machine: both sides are rewritten without them,
# with sorted keys, one value per line.
without_run_facts() {
  python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
for k in ("timings", "peak_memory_mb", "memory_estimate_mb", "machine"):
    d.pop(k, None)
print(json.dumps(d, indent=1, sort_keys=True))' "$1" > "$2"
}

failed=0
while IFS= read -r -d '' reference; do
  relative=${reference#"$srcdir/$name.expected/"}
  if [ ! -f "$relative" ]; then
    echo "FAIL: $relative was not written"
    failed=1
    continue
  fi
  expected_file=$reference
  written_file=$relative
  if [ "${relative##*.}" = json ]; then
    expected_file=$(mktemp) written_file=$(mktemp)
    without_run_facts "$reference" "$expected_file"
    without_run_facts "$relative" "$written_file"
  fi
  if numdiff -q -r 1e-6 -a 1e-9 -s ' \t\n,[]{}:"' "$expected_file" \
      "$written_file" > /dev/null; then
    echo "OK: $relative"
  else
    echo "FAIL: $relative differs from the reference:"
    numdiff -r 1e-6 -a 1e-9 -s ' \t\n,[]{}:"' "$expected_file" "$written_file" |
      head -40
    failed=1
  fi
done < <(find "$srcdir/$name.expected" -type f -print0 | sort -z)
exit $failed
