#!/usr/bin/env bash
# fetch_cbmc.sh <root>: CBMC 6.6.0 from Debian 13 (trixie) into the private root <root>, for the model-checking
# harnesses of tests/cbmc (docs/verification.md). Debian 12 packages no CBMC; trixie's needs a newer C and C++
# library than Debian 12 has, so the root holds those too and <root>/cbmc starts CBMC through the root's own
# loader. Nothing is installed system-wide: apt runs with a private configuration, state and cache under
# <root>/apt, fetches the pinned packages below (checked against the SHA-256 sums here, on top of apt's own
# check against the archive's signed index) and dpkg-deb unpacks them into <root>/sys.
# A pinned version that the archive has dropped (a point release replaced libc6) is fetched from
# snapshot.debian.org at PAC_CBMC_SNAPSHOT instead; update the pins and sums with a new trixie release.
set -euo pipefail

root=${1:?usage: fetch_cbmc.sh <root>}
mkdir -p "$root"
root=$(cd "$root" && pwd)
# name=version sha256
pins=(
  "cbmc=6.6.0-4 02560859a17049c976961c232c4fc58f0747b57f9b751a466b1f368a438b0e41"
  "minisat=1:2.2.1-8 0b3a870202e022bea8b04d140ded40d9137363566706750b4540518bc0eb63d7"
  "libc6=2.41-12+deb13u5 b59b0625cd1a791375d40dab23a4d5d3d0641e3d0a773501becdc3725b7f99cf"
  "libstdc++6=14.2.0-19 ab1fa05837aa7a92aae748fd07a18a35f7d18bb4a71c4724fe2bbf0e32089de0"
  "libgcc-s1=14.2.0-19 3c71917b490d1a17aed43196a2787a256ecf060526cdb20216a74bedc061b150"
  "zlib1g=1:1.3.dfsg+really1.3.1-1+deb13u1 8c27c342230503b73dfde629642c3b352e87b554e06d60cf58772f236a305ceb"
)
stamp="$root/.pins-$(printf '%s\n' "${pins[@]}" | sha256sum | cut -c1-16)"
if [ -f "$stamp" ] && [ -x "$root/cbmc" ]; then
  exit 0
fi
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
[ -f "$keyring" ] || { echo "fetch_cbmc.sh: $keyring missing (apt-get install debian-archive-keyring)" >&2; exit 1; }
snapshot=${PAC_CBMC_SNAPSHOT:-20251201T000000Z}

apt_dir="$root/apt"
rm -rf "$apt_dir" "$root/sys"
mkdir -p "$apt_dir"/{etc/apt.conf.d,etc/preferences.d,etc/sources.list.d,state/lists/partial,cache/archives/partial,debs}
touch "$apt_dir/status"
cat > "$apt_dir/apt.conf" <<CONF
Dir "$apt_dir/";
Dir::Etc "$apt_dir/etc/";
Dir::Etc::sourcelist "$apt_dir/etc/sources.list";
Dir::Etc::sourceparts "$apt_dir/etc/sources.list.d/";
Dir::Etc::parts "$apt_dir/etc/apt.conf.d/";
Dir::Etc::preferencesparts "$apt_dir/etc/preferences.d/";
Dir::State "$apt_dir/state/";
Dir::State::status "$apt_dir/status";
Dir::Cache "$apt_dir/cache/";
APT::Architecture "amd64";
APT::Architectures { "amd64"; };
Acquire::Languages "none";
Acquire::IndexTargets::deb::DEP-11::DefaultEnabled "false";
Acquire::IndexTargets::deb::DEP-11-icons::DefaultEnabled "false";
Acquire::IndexTargets::deb::DEP-11-icons-small::DefaultEnabled "false";
Acquire::IndexTargets::deb::CNF::DefaultEnabled "false";
Debug::NoLocking "true";
APT::Sandbox::User "root";
CONF
export APT_CONFIG="$apt_dir/apt.conf"

fetch() {  # fetch <sources.list line>: the pinned packages into debs/, from that archive
  echo "$1" > "$apt_dir/etc/sources.list"
  apt-get -qq update || return 1
  local names=() p
  for p in "${pins[@]}"; do names+=("${p%% *}"); done
  (cd "$apt_dir/debs" && apt-get -qq download "${names[@]}") || return 1
}
echo "fetch_cbmc.sh: fetching CBMC 6.6.0 and its libraries from Debian trixie into $root"
if ! fetch "deb [signed-by=$keyring] http://deb.debian.org/debian trixie main"; then
  echo "fetch_cbmc.sh: not all pinned versions in the archive; trying snapshot.debian.org/archive/debian/$snapshot" >&2
  rm -f "$apt_dir/debs"/*.deb
  fetch "deb [signed-by=$keyring check-valid-until=no] http://snapshot.debian.org/archive/debian/$snapshot trixie main"
fi

mkdir -p "$root/sys"
for p in "${pins[@]}"; do
  name=${p%%=*}
  sum=${p##* }
  deb=$(ls "$apt_dir/debs/${name}_"*.deb)
  echo "$sum  $deb" | sha256sum --quiet -c - || { echo "fetch_cbmc.sh: $deb: SHA-256 differs from the pin" >&2; exit 1; }
  dpkg-deb -x "$deb" "$root/sys"
done

# CBMC preprocesses with the machine's gcc (Debian 12's), and runs on the root's own loader and libraries.
cat > "$root/cbmc" <<WRAP
#!/bin/sh
sys="$root/sys"
exec "\$sys/usr/lib/x86_64-linux-gnu/ld-linux-x86-64.so.2" \\
  --library-path "\$sys/usr/lib/x86_64-linux-gnu:\$sys/usr/lib" "\$sys/usr/bin/cbmc" "\$@"
WRAP
chmod +x "$root/cbmc"
"$root/cbmc" --version > /dev/null
rm -rf "$apt_dir"
rm -f "$root"/.pins-*
touch "$stamp"
echo "fetch_cbmc.sh: $("$root/cbmc" --version) in $root/cbmc"
