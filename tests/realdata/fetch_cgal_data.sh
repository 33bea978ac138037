#!/usr/bin/env bash
# fetch_cgal_data.sh SOURCE_DIR DEST: CGAL's demo data (Debian's libcgal-demo,
# installed like the project's other packages when missing) unpacked into
# DEST/data, with the OFF meshes the real-data tests use converted to OBJ
# (DEST/meshes/NAME.obj). Does nothing that is already done.
set -euo pipefail
source_dir=$1
dest=$2
"$source_dir/scripts/install_packages.sh" libcgal-demo
archive=/usr/share/doc/libcgal-dev/data.tar.gz
mkdir -p "$dest"
if [[ ! -d "$dest/data/points_3" ]]; then
  tar -xzf "$archive" -C "$dest" data/points_3 data/meshes
fi
mkdir -p "$dest/meshes"
for name in bunny00 armadillo elephant fandisk; do
  if [[ ! -s "$dest/meshes/$name.obj" ]]; then
    python3 "$source_dir/tests/realdata/off_to_obj.py" "$dest/data/meshes/$name.off" "$dest/meshes/$name.obj"
  fi
done
