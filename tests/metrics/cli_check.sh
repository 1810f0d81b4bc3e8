#!/bin/sh
# cli_check.sh TOOL DATA_DIR WORK_DIR CASE
# Runs vtkshadow-metrics for one case and checks the exit status, the
# message, and the files left behind. Bad input must exit 2, name the file
# or option and the value on stderr, and write no output file.
set -u
tool=$1 data=$2 work=$3 case=$4

rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
R=$data/ref16.png M=$data/mask8.png T=$data/test16.png
fail=0
say() { echo "cli_check[$case]: $*" >&2; fail=1; }

# run EXPECTED_STATUS ARGS...: output in out.txt / err.txt
run() {
  want=$1; shift
  "$tool" "$@" >out.txt 2>err.txt
  got=$?
  [ "$got" -eq "$want" ] || say "exit status $got, expected $want (args: $*)"
  # sanitizer builds: a report is a failure even when the status matches
  ! grep -q 'Sanitizer\|runtime error' err.txt || say "sanitizer report: $(cat err.txt)"
}
err_has() { grep -F -q -- "$1" err.txt || say "stderr lacks '$1': $(cat err.txt)"; }
out_has() { grep -F -q -- "$1" out.txt || say "stdout lacks '$1': $(cat out.txt)"; }
# bad input: status 2, message, nothing written, nothing on stdout
bad() {
  msg=$1; shift
  run 2 "$@" --json out.json --heatmap heat.png
  err_has "$msg"
  [ ! -e out.json ] || say "out.json was written"
  [ ! -e heat.png ] || say "heat.png was written"
  [ ! -s out.txt ] || say "stdout not empty: $(cat out.txt)"
}
no_tmp() {
  for f in *.tmp*; do [ -e "$f" ] && say "temporary file left: $f"; done
}

case $case in
  ok)
    run 0 --reference "$R" --mask "$M" --test "$T" --json out.json --heatmap heat.png
    out_has '"reference": "'"$R"'"'
    out_has '"exclude": null'
    out_has '"valid_pixels": 56,'
    out_has '"compared_pixels": 56,'
    out_has '"vis_mae": 0.125,'
    out_has '"wrong_pct": 12.5,'
    out_has '"edge_px": 1,'
    out_has '"false_shadow_pct": 12.5,'
    out_has '"false_light_pct": 0,'
    # shadow: columns 0-3 of rows 1-7 (28), test 0-4 (35); 7 wrong
    out_has '"ref_shadow_pixels": 28,'
    out_has '"test_shadow_pixels": 35,'
    out_has '"wrong_of_shadow_pct": 25,'
    out_has '"wrong_of_test_shadow_pct": 20,'
    # penumbra figures: the hard reference has no penumbra; 7 of its 28
    # lit pixels are dark in the test
    out_has '"pen_pixels": 0,'
    out_has '"pen_mae": 0,'
    out_has '"pen_false_shadow_pct": 25,'
    grep -x -q '  "pen_width_ratio": 0' out.txt ||
      say "stdout lacks the last line pen_width_ratio 0: $(cat out.txt)"
    cmp -s out.txt out.json || say "--json file differs from stdout"
    [ -s heat.png ] || say "no heat map written"
    head -c 8 heat.png | od -An -c | grep -q 'P   N   G' || say "heat map is not a PNG"
    [ ! -s err.txt ] || say "unexpected stderr: $(cat err.txt)"
    no_tmp ;;
  band)
    run 0 --reference "$R" --mask "$M" --test "$T" --band 1
    out_has '"band": 1,'
    out_has '"compared_pixels": 42,'
    out_has '"wrong_pct": 0,'
    out_has '"edge_px": 1,'
    # columns 3 and 4 leave: both shadows are columns 0-2 (21 pixels)
    out_has '"ref_shadow_pixels": 21,'
    out_has '"test_shadow_pixels": 21,'
    out_has '"wrong_of_shadow_pct": 0,' ;;
  exclude)
    run 0 --reference "$R" --mask "$M" --test "$T" --exclude "$data/exclude_right8.png"
    out_has '"compared_pixels": 28,'
    out_has '"wrong_pct": 0,'
    out_has '"exclude": "'"$data/exclude_right8.png"'"' ;;
  empty)
    # nothing to compare: metrics printed (all 0), warning, status 3
    run 3 --reference "$R" --mask "$data/mask_empty8.png" --test "$T"
    out_has '"compared_pixels": 0,'
    err_has 'no pixel compared' ;;
  help)
    run 0 --help
    out_has 'Usage: vtkshadow-metrics' ;;
  missing_option)
    bad 'missing required option --test' --reference "$R" --mask "$M" ;;
  missing_value)
    run 2 --reference "$R" --mask "$M" --test
    err_has '--test: missing value' ;;
  unknown_option)
    bad "unknown option '--frobnicate'" --reference "$R" --mask "$M" --test "$T" --frobnicate 1 ;;
  duplicate_option)
    bad "--test given twice ('$T' and '$R')" --reference "$R" --mask "$M" --test "$T" --test "$R" ;;
  unreadable)
    bad "$data/nonexistent.png: cannot open (No such file or directory)" \
      --reference "$R" --mask "$M" --test "$data/nonexistent.png" ;;
  not_png)
    bad "$data/not_png.png: not a PNG file" --reference "$data/not_png.png" --mask "$M" --test "$T" ;;
  truncated)
    bad "$data/truncated.png: corrupt" --reference "$R" --mask "$M" --test "$data/truncated.png" ;;
  rgb)
    bad "$data/rgb8.png: expected grayscale, got RGB" --reference "$R" --mask "$data/rgb8.png" --test "$T" ;;
  gray_alpha)
    bad "$data/gray_alpha8.png: expected grayscale, got gray+alpha" \
      --reference "$R" --mask "$M" --test "$data/gray_alpha8.png" ;;
  size_mismatch)
    bad "$data/small8x6.png is 8x6 but $R is 8x8" --reference "$R" --mask "$M" --test "$data/small8x6.png" ;;
  exclude_size_mismatch)
    bad "$data/small8x6.png is 8x6 but $R is 8x8" \
      --reference "$R" --mask "$M" --test "$T" --exclude "$data/small8x6.png" ;;
  band_negative)
    bad "--band: expected a whole number >= 0, got '-1'" --reference "$R" --mask "$M" --test "$T" --band -1 ;;
  band_junk)
    bad "--band: expected a whole number >= 0, got '2x'" --reference "$R" --mask "$M" --test "$T" --band 2x ;;
  band_overflow)
    bad "--band: expected a whole number >= 0, got '99999999999999999999'" \
      --reference "$R" --mask "$M" --test "$T" --band 99999999999999999999 ;;
  empty_value)
    bad "--mask: empty value" --reference "$R" --mask "" --test "$T" ;;
  unwritable_json)
    # not bad input but a failed write: status 1, message, nothing on stdout
    run 1 --reference "$R" --mask "$M" --test "$T" --json no/such/dir/out.json
    err_has 'no/such/dir/out.json: cannot create temporary file'
    [ ! -s out.txt ] || say "stdout not empty" ;;
  reflection_ok)
    C=$data/ref_rgb8.png CT=$data/test_rgba16.png
    run 0 --reflection --reference "$C" --mask "$M" --test "$CT" --json out.json --heatmap heat.png
    out_has '"metric": "reflection",'
    out_has '"mirror_pixels": 56,'
    out_has '"compared_pixels": 56,'
    out_has '"reflection_mae": 0.03333333'
    cmp -s out.txt out.json || say "--json file differs from stdout"
    head -c 8 heat.png | od -An -c | grep -q 'P   N   G' || say "heat map is not a PNG"
    [ ! -s err.txt ] || say "unexpected stderr: $(cat err.txt)" ;;
  reflection_exclude)
    run 0 --reference "$data/ref_rgb8.png" --mask "$M" --test "$data/test_rgba16.png" \
      --exclude "$data/exclude_right8.png" --reflection
    out_has '"compared_pixels": 28,'
    grep -x -q '  "reflection_mae": 0' out.txt || say "reflection_mae is not 0: $(cat out.txt)" ;;
  reflection_empty)
    run 3 --reflection --reference "$data/ref_rgb8.png" --mask "$data/mask_empty8.png" \
      --test "$data/test_rgba16.png"
    out_has '"compared_pixels": 0,'
    err_has 'no mirror pixel compared' ;;
  reflection_gray)
    bad "$R: expected RGB or RGBA, got grayscale" --reflection --reference "$R" --mask "$M" \
      --test "$data/test_rgba16.png" ;;
  reflection_band)
    bad "--band '1': not with --reflection" --reflection --reference "$data/ref_rgb8.png" \
      --mask "$M" --test "$data/test_rgba16.png" --band 1 ;;
  reflection_twice)
    bad "--reflection given twice" --reflection --reference "$data/ref_rgb8.png" \
      --mask "$M" --test "$data/test_rgba16.png" --reflection ;;
  reflection_size_mismatch)
    bad "$data/small8x6.png is 8x6 but $data/ref_rgb8.png is 8x8" --reflection \
      --reference "$data/ref_rgb8.png" --mask "$data/small8x6.png" --test "$data/test_rgba16.png" ;;
  *)
    say "unknown case"; exit 1 ;;
esac
no_tmp
[ $fail -eq 0 ] && echo "cli_check[$case]: ok"
exit $fail
