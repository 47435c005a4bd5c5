#!/usr/bin/env bash
# Renders the pictures of README.md and docs/ from the bundled scenarios, so they show what the
# program draws today and anyone can make them again:
#
#   docs/make_images.sh [SYLVA]        SYLVA: the sylva binary (default build/bin/sylva)
#
# Writes docs/images/:
#   default.png                     a frame of the default scenario (480x270)
#   representation_<name>.png       the same frame per representation and with SH lighting
#                                   (320x180 each): mesh_levels, points_lines, billboard_clouds, sh
#   representations.png             those four side by side, labelled
#   implicit_lighting.png           single_tree lit by its leaves' normals and by Luft 2007's
#                                   implicit surface, photo and lines styles, labelled (2x2)
#
# Environment: FRAME (the frame of the default camera path to show, default 8, i.e. t = 8/24 s:
# the camera looks over the meadow at a solitary oak with the wood behind; `play` always starts
# at t = 0, so FRAME+1 frames are played and the last is kept), OUT (default docs/images).
# Headless through OSMesa; on a CPU rasteriser (llvmpipe, two cores) it takes a few minutes, and
# the first points_lines or sh run bakes into the bake cache ($SYLVA_CACHE_DIR) first.
#
# Needs oiiotool (Debian package openimageio-tools, which ./sylva installs), pngquant (Debian
# package pngquant; it brings the PNGs to a 256-colour palette: the pictures stay a few hundred
# KB in git) and the DejaVu font (fonts-dejavu-core) for the labels.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sylva="${1:-$here/build/bin/sylva}"
frame="${FRAME:-8}"
out="${OUT:-$here/docs/images}"
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf

need() {  # command, Debian package
  command -v "$1" >/dev/null || { echo "make_images: $1 not found: apt-get install $2" >&2; exit 1; }
}
need oiiotool openimageio-tools
need pngquant pngquant
[ -f "$font" ] || { echo "make_images: $font not found: apt-get install fonts-dejavu-core" >&2; exit 1; }
[ -x "$sylva" ] || { echo "make_images: no sylva binary at $sylva (./sylva build makes build/bin/sylva)" >&2; exit 1; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# play SCENARIO for FRAMES frames at W x H with the given options; prints the last frame's path.
play_last() {
  local scenario="$1" frames="$2" name="$3" width="$4" height="$5"
  shift 5
  echo "[make_images] $name: sylva play $scenario --frames $frames --width $width --height $height $*" >&2
  "$sylva" play "$scenario" --headless --frames "$frames" --width "$width" --height "$height" \
    --out "$work/$name" "$@" >"$work/$name.log" 2>&1 || { cat "$work/$name.log" >&2; exit 1; }
  printf '%s/%s/frame_%04d.png\n' "$work" "$name" "$((frames - 1))"
}

# play default, FRAME+1 frames at W x H with the given options; prints the last frame's path.
render() {
  local name="$1" width="$2" height="$3"
  shift 3
  play_last default "$((frame + 1))" "$name" "$width" "$height" "$@"
}

# A frame with its label in the top left corner, for a mosaic.
label_tile() {  # in, label, out
  oiiotool "$1" --text:x=8:y=20:size=14:color=0.05,0.12,0.05:font="$font" "$2" -o "$3"
}

# Quantise to a palette: foliage is noise to a PNG compressor, 24-bit frames are 3x larger.
shrink() {  # in, out
  pngquant --quality 70-95 --speed 1 --strip --force --output "$2" "$1"
}

shrink "$(render default 480 270)" "$out/default.png"

tiles=()
for rep in mesh_levels points_lines billboard_clouds sh; do
  case "$rep" in
    sh) opts=(--representation mesh_levels --lighting sh) label="mesh levels, SH lighting" ;;
    mesh_levels) opts=(--representation mesh_levels) label="mesh levels" ;;
    points_lines) opts=(--representation points_lines) label="points and lines" ;;
    billboard_clouds) opts=(--representation billboard_clouds) label="billboard clouds" ;;
  esac
  frame_png="$(render "$rep" 320 180 "${opts[@]}")"
  shrink "$frame_png" "$out/representation_$rep.png"
  label_tile "$frame_png" "$label" "$work/tile_$rep.png"
  tiles+=("$work/tile_$rep.png")
done
oiiotool "${tiles[@]}" --mosaic:pad=4 4x1 -o "$work/representations.png"
shrink "$work/representations.png" "$out/representations.png"

# Luft 2007 Figures 1 and 7: the tree's own normals against the implicit surface's.
tree_tiles=()
for variant in normal_photo implicit_photo normal_lines implicit_lines; do
  lighting="${variant%_*}" style="${variant#*_}"
  [ "$lighting" = normal ] && lighting=normal_mapped
  frame_png="$(play_last single_tree 1 "$variant" 320 180 --lighting "$lighting" --style "$style")"
  case "$variant" in
    normal_photo) label="leaf normals" ;;
    implicit_photo) label="implicit surface (Luft 2007)" ;;
    normal_lines) label="leaf normals, lines" ;;
    implicit_lines) label="implicit surface, lines" ;;
  esac
  label_tile "$frame_png" "$label" "$work/tile_$variant.png"
  tree_tiles+=("$work/tile_$variant.png")
done
oiiotool "${tree_tiles[@]}" --mosaic:pad=4 2x2 -o "$work/implicit_lighting.png"
shrink "$work/implicit_lighting.png" "$out/implicit_lighting.png"

du -cb "$out"/*.png | tail -1 | awk '{printf "[make_images] %d KB in docs/images\n", $1 / 1024}' >&2
