#!/usr/bin/env bats
# The layers of lib/ run one way (DESIGN.md "Layout"): tests/layers.sh,
# which holds the layer order, finds no include that points up in the
# source tree, and does find one planted in a copy of it.

bats_require_minimum_version 1.5.0
load helpers

setup() {
	[ -d "$ROOT/lib" ] || skip "no source tree at $ROOT"
}

@test "layers: every include in lib/ points down" {
	run sh "$ROOT/tests/layers.sh"
	echo "$output"
	[ "$status" -eq 0 ]
	[ -z "$output" ]
}

@test "layers: an include that points up, an algorithm on its front end, an unlisted folder all fail" {
	T=$BATS_TEST_TMPDIR
	mkdir -p "$T/lib"
	cp -r "$ROOT/lib/core" "$ROOT/lib/io" "$ROOT/lib/fe" "$ROOT/lib/detect" "$T/lib/"
	sed -i '1a #include "fe/hex8.h"' "$T/lib/io/vtk.c"
	sed -i 's|#include "detect/algo.h"|#include "detect/detect.h"|' "$T/lib/detect/brute.c"
	mkdir "$T/lib/extra"
	echo '#include "core/error.h"' > "$T/lib/extra/x.c"
	run sh "$ROOT/tests/layers.sh" "$T"
	echo "$output"
	[ "$status" -eq 1 ]
	[ "${#lines[@]}" -eq 3 ]
	[[ ${lines[*]} == *"lib/io/vtk.c:2: includes fe/hex8.h: io does not sit above fe"* ]]
	[[ ${lines[*]} == *"lib/detect/brute.c:"*": includes its folder's front end detect/detect.h"* ]]
	[[ ${lines[*]} == *"lib/extra/x.c: the folder extra is not in the layer order"* ]]
}
