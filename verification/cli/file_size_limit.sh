# Sourced by write_failures.sh and write_failures_components.sh (not a test).
# limited LIMIT_KB ARGS...: "$rsi" ARGS under a file-size limit of LIMIT_KB
# with SIGXFSZ ignored (a write past the limit then fails with EFBIG, as
# one on a full disk fails with ENOSPC); stdout to $work/log, stderr to
# $work/err, the exit status returned.
limited() {
  local limit=$1
  shift
  (
    trap '' XFSZ
    ulimit -f "$limit"
    "$rsi" "$@"
  ) >"$work/log" 2>"$work/err"
}
