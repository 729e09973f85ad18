# Sourced by the setup scripts: ensure_packages WHO PACKAGE... installs the Debian packages
# that are missing (as root), or prints the one apt-get line to run and exits 1.
ensure_packages() {
  local who=$1 p
  shift
  local missing=()
  # One dpkg-query for them all (a launch of ./run.sh waits on this): the installed ones.
  local installed
  installed=$(dpkg-query -W -f='${Package} ${Status}\n' "$@" 2>/dev/null |
    awk '/install ok installed/ {print $1}' || true)
  for p in "$@"; do
    grep -qx -- "$p" <<<"$installed" || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  if [[ $(id -u) -eq 0 ]]; then
    echo "$who: installing ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "$who: missing packages. Run this once, then try again:"
    echo "  sudo apt-get install -y --no-install-recommends ${missing[*]}"
    exit 1
  fi
}
