# Sourced by the end-to-end tests that build the gmsh blade or run ccx: a
# test that cannot run says why and exits 77, which ctest counts as skipped
# (SKIP_RETURN_CODE 77), never as passed.
for tool in gmsh ccx; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not on PATH (Debian packages gmsh, calculix-ccx)"
    exit 77
  fi
done
