# Sourced by the set-up scripts: aniso_install_packages PACKAGE... installs the Debian 12
# packages that are missing (apt-get as root; otherwise prints the line to run and fails).
aniso_install_packages() {
  local missing=() p
  for p in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  if [ "$(id -u)" -eq 0 ]; then
    echo "aniso: installing missing packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "aniso: missing Debian packages: ${missing[*]}" >&2
    echo "aniso: install them with: sudo apt-get install ${missing[*]}" >&2
    return 1
  fi
}
