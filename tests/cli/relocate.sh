#!/bin/sh
# A built tree can move: adhere finds share/adhere beside its own executable
# (/proc/self/exe), not where it was built; $ADHERE_DATADIR overrides that;
# a lone binary falls back to the install prefix and says where it looked.
# Prints TAP.
. "$(dirname "$0")/lib.sh"
SRC=${ADHERE_SRC:-$PWD}
unset ADHERE_DATADIR
# The built tree's layout, copied: the program and its data beside it.
M=$TMP/moved
mkdir -p "$M"
cp -p "$ADHERE" "$M/adhere"
cp -pR "$SRC/share" "$M/share"
sed -i 's/^title = .*/title = the moved copy of the default scene/' "$M/share/adhere/scenes/default.scene"
"$M/adhere" --plan default >"$TMP/plan" 2>"$TMP/err"
check "the moved copy reads its own scene (exit $?: $(head -1 "$TMP/plan"))" \
    grep -q "^plan: the moved copy of the default scene" "$TMP/plan"
check "and says it found it beside itself" grep -qF "scene: $M/share/adhere/scenes/default.scene" "$TMP/plan"
"$ADHERE" --plan default >"$TMP/plan0" 2>&1
check "the original still reads the tree's own ($(head -1 "$TMP/plan0"))" \
    sh -c "grep -q '^plan: Default' '$TMP/plan0' && grep -qF 'scene: $SRC/share/adhere/scenes/default.scene' '$TMP/plan0'"
# $ADHERE_DATADIR comes before the data beside the executable.
D=$TMP/data
mkdir -p "$D/scenes"
sed 's/^title = .*/title = the scene of ADHERE_DATADIR/' "$SRC/share/adhere/scenes/default.scene" >"$D/scenes/default.scene"
ADHERE_DATADIR=$D "$M/adhere" --plan default >"$TMP/plan2" 2>&1
check "ADHERE_DATADIR overrides the data beside the executable" grep -q "^plan: the scene of ADHERE_DATADIR" "$TMP/plan2"
# A binary with no data beside it (and, here, none installed under its
# prefix) finds no scene, and names every place it looked.
mkdir -p "$TMP/lone"
cp -p "$ADHERE" "$TMP/lone/adhere"
"$TMP/lone/adhere" --plan fig4 >"$TMP/plan3" 2>"$TMP/err3"
rc=$?
if [ -d /usr/local/share/adhere/scenes ]; then
    check "a lone binary reads the installed scenes" grep -q "^scene: /usr/local/share/adhere/scenes/fig4.scene" "$TMP/plan3"
else
    check "a lone binary exits 2 and names where it looked ($(cat "$TMP/err3"))" \
        sh -c "[ $rc -eq 2 ] && grep -qF '$TMP/lone/share/adhere/scenes' '$TMP/err3' && grep -q 'share/adhere/scenes' '$TMP/err3'"
fi
done_testing
