# Installs what the build needs, only when missing (quick when everything is there).
# Sourced by run.sh and test.sh:  ensure_debian_packages PKG...;  ensure_npm_packages
# Everything comes from Debian's archive and the npm registry; nothing else is downloaded.

ensure_debian_packages() {
  local missing=()
  for package in "$@"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "Installing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  # Retries ride out a mirror's brief hiccup, which would otherwise fail a whole CI run.
  $sudo apt-get -o Acquire::Retries=5 update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get -o Acquire::Retries=5 install -y -q \
    --no-install-recommends "${missing[@]}"
}

ensure_npm_packages() {
  # npm ci installs exactly the committed lock file; a stamp of the lock's hash skips it next time.
  local stamp=node_modules/.installed-lock.sha256
  local want
  want=$(sha256sum package-lock.json | cut -d' ' -f1)
  if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
    npm ci --no-audit --no-fund --fetch-retries=5
    echo "$want" >"$stamp"
  fi
}

# Debian's Emscripten needs its JS optimizer's acorn from Debian's node-acorn.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

WEB_PACKAGES=(emscripten node-acorn libglm-dev nlohmann-json3-dev libstb-dev libtinyobjloader-dev cmake make)
NATIVE_PACKAGES=(g++ cmake make pkg-config libglm-dev nlohmann-json3-dev libembree-dev libstb-dev libtinyobjloader-dev libgtest-dev
                 libgles-dev libegl-dev libegl-mesa0 libgl1-mesa-dri clang lld libclang-rt-14-dev clang-format
                 libcli11-dev)
BROWSER_PACKAGES=(chromium)
