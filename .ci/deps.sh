# Sourced by run-main.sh, run-tests.sh and .ci/run: installs the Debian
# packages rsi needs when any is missing (apt-get; as root, or through sudo).
rsi_packages=(build-essential cmake pkg-config libeigen3-dev libsuitesparse-dev liblapacke-dev libgsl-dev
  libgtest-dev libspectra-dev nlohmann-json3-dev libcli11-dev libbenchmark-dev python3-matplotlib
  python3-scipy python3-numpy calculix-ccx calculix-ccx-test gmsh libopenblas0-pthread libopenblas-dev
  libopenmpi-dev openmpi-bin ninja-build strace)

# New build trees are Ninja's (an existing tree keeps the generator it was
# made with: CMake reads CMAKE_GENERATOR only when it creates one). Ninja
# compiles a target's files while the libraries it links are still being
# built; with CMake's Makefiles they wait for them, and the 2-core machine's
# sanitizer build kept 76 % of its cores busy (session 32: 2,305 s of CPU in
# 1,523 s, the Release build 92 %).
export CMAKE_GENERATOR=${CMAKE_GENERATOR:-Ninja}

rsi_install_dependencies() {
  local missing=()
  local p
  for p in "${rsi_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
}
