#!/usr/bin/env bash
# fetch-simh.sh DESTDIR: get Debian's simh 3.8.1 source with apt's source-package
# support, from this machine's own apt sources, check the orig tarball, unpack it.
#
# Source entries are often not enabled, so a private apt configuration under
# DESTDIR/apt is derived from the system's (binary) entries by turning them into
# deb-src entries. Only the orig tarball is needed: the Debian diff may be absent.
set -euo pipefail
dest=$(realpath -m "$1")
version=3.8.1
debver=3.8.1-6.1
sha=64ef4c4f19125cced9e47913d732ed34d9ca72e83e33dc8ca97c40cf2f081a6f
tarball="$dest/simh_$version.orig.tar.gz"

if [ -f "$dest/simh-$version/scp.c" ]; then exit 0; fi
mkdir -p "$dest/apt/sources.list.d" "$dest/apt/lists/partial" "$dest/apt/cache/archives/partial"

if [ ! -f "$tarball" ]; then
  echo "==> fetching the simh $debver source package with apt-get source"
  # deb822 .sources files: Types: deb -> deb-src
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -e "$f" ] || continue
    sed -e 's/^Types:.*$/Types: deb-src/' "$f" > "$dest/apt/sources.list.d/$(basename "$f")"
  done
  # one-line format: deb ... -> deb-src ...
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -e "$f" ] || continue
    grep -E '^[[:space:]]*deb[[:space:]]' "$f" | sed -E 's/^[[:space:]]*deb[[:space:]]/deb-src /' \
      > "$dest/apt/sources.list.d/$(basename "$f" .list)-src.list" || true
  done
  cat > "$dest/apt/apt.conf" <<CONF
Dir::Etc::SourceList "/dev/null";
Dir::Etc::SourceParts "$dest/apt/sources.list.d";
Dir::State::Lists "$dest/apt/lists";
Dir::Cache "$dest/apt/cache";
APT::Sandbox::User "root";
CONF
  export APT_CONFIG="$dest/apt/apt.conf"
  apt-get -o DPkg::Lock::Timeout=300 update -qq
  # The Debian diff can be missing from the archive; apt then fails after the
  # orig tarball has arrived, which is all we use. Judge by the tarball.
  (cd "$dest" && apt-get source --download-only -qq "simh=$debver" 2>"$dest/apt/source.log") ||
    echo "==> simh source: apt reported a missing file (see $dest/apt/source.log); only the orig tarball is needed"
  if [ ! -f "$tarball" ]; then
    echo "error: apt-get source did not deliver simh_$version.orig.tar.gz" >&2
    echo "       (check that this machine's apt sources carry Debian's simh $debver)" >&2
    exit 1
  fi
fi

echo "$sha  $tarball" | sha256sum --check --quiet || {
  echo "error: $tarball does not have the expected sha256 $sha" >&2; exit 1; }
echo "==> unpacking simh $version under $dest"
tar -xzf "$tarball" -C "$dest"
test -f "$dest/simh-$version/scp.c"
