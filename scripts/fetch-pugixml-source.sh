#!/usr/bin/env bash
# The source of the pugixml that libpugixml-dev installs (make fuzz): Debian ships only the
# compiled library, which the fuzzer cannot see into. Downloads the same version's source
# package with apt-get (a private list of Debian's source archive, the system's own lists
# untouched), unpacks it into DIR and prints DIR/src, where pugixml.cpp is. Does nothing when
# DIR/src/pugixml.cpp is there and its header is the installed one.
set -euo pipefail
dir=${1:?usage: $0 DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
if [ -f "$dir/src/pugixml.cpp" ] && cmp -s "$dir/src/pugixml.hpp" /usr/include/pugixml.hpp; then
    echo "$dir/src"
    exit 0
fi
version=$(dpkg-query -W -f='${Version}' libpugixml-dev)
apt_dir="$dir/apt"
mkdir -p "$apt_dir/lists/partial"
codename=$(. /etc/os-release && echo "$VERSION_CODENAME")
echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $codename main" \
    >"$apt_dir/sources.list"
apt=(apt-get -q -o Dir::Etc::SourceList="$apt_dir/sources.list" -o Dir::Etc::SourceParts=/nonexistent
     -o Dir::State::Lists="$apt_dir/lists")
"${apt[@]}" update >&2
(cd "$apt_dir" && "${apt[@]}" source --download-only "pugixml=$version" >&2)
rm -rf "$dir/src"
mkdir -p "$dir/unpack"
tar -xzf "$apt_dir"/pugixml_*.orig.tar.gz -C "$dir/unpack"
mv "$dir"/unpack/pugixml-*/src "$dir/src"
rm -rf "$dir/unpack"
if ! cmp -s "$dir/src/pugixml.hpp" /usr/include/pugixml.hpp; then
    echo "fetch-pugixml-source: the source's pugixml.hpp differs from the installed one" >&2
    exit 1
fi
echo "$dir/src"
