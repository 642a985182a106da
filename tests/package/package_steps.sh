# Sourced by the package tests: a temporary directory removed on exit, weathergen
# installed into $prefix there, and the two step helpers.
#
# usage: source package_steps.sh NAME BUILD_DIR CMAKE   (sets tmp and prefix)

tmp=$(mktemp -d "${TMPDIR:-/tmp}/wg-$1.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Runs a command quietly; on failure prints its output and fails with the message.
quiet() {
  local what=$1
  shift
  "$@" >"$tmp/step.log" 2>&1 || { cat "$tmp/step.log" >&2; fail "$what"; }
}

quiet "cmake --install" "$3" --install "$2" --prefix "$prefix"
