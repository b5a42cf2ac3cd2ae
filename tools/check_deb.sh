#!/usr/bin/env bash
# Builds the Debian package of a built tree (cpack -G DEB, cmake/CollidoPackage.cmake), installs
# it with apt-get (as root: it goes under /usr), and runs the installed tool: `collido backends`
# and one `collido run` on an installed scene. CI runs it; by hand:
#   tools/check_deb.sh build/release [--keep]
# --keep leaves the package installed; otherwise it is removed again at the end.
set -euo pipefail
build=$(realpath "$1")
keep=${2:-}
cd "$build"
rm -f collidoscope_*.deb
cpack -G DEB > cpack.log
deb=$(ls collidoscope_*.deb)
echo "== $deb: $(du -h "$deb" | cut -f1)"
dpkg-deb --field "$deb" Package Version Depends
apt-get install -y -qq "./$deb" > apt.log
trap '[[ $keep == --keep ]] || apt-get purge -y -qq collidoscope > /dev/null' EXIT

echo "== /usr/bin/collido backends"
(cd / && /usr/bin/collido backends) | tee backends.out
grep -q "^obbtree" backends.out
echo "== /usr/bin/collido run on an installed scene"
# Exit 0: no backend failed (FCL's contact points are off the exact set here, a known finding
# that the table shows, not a failure).
(cd / && /usr/bin/collido run /usr/share/collido/scenes/interlocked_tori.json \
  --backends obbtree,fcl:obb --repetitions 1)
echo "Debian package check passed"
