# A seeded generator the shell tests draw noise from, the same numbers under
# any awk (srand/rand are each awk's own: mawk and gawk draw different
# ones): drand48's, seeded as srand48(SEED) seeds it,
# X' = (a X + 11) mod 2^48, a = 1502 2^24 + 15525485, its products split
# at 2^24 so that every one is an exact integer in a double. Read it with
# awk -f "$DRAND48" -f script, call srand48(seed) in the script's BEGIN;
# urand() is uniform on [0, 1), gauss() a standard normal (Box-Muller).
function srand48(seed) {X = seed * 65536 + 13070}
function mod(x, m) {return x - m * int(x / m)}
function urand(  lo) {
    lo = mod(X, 16777216)
    X = mod(15525485 * lo + 16777216 * mod(1502 * lo + 15525485 * (X - lo) / 16777216, 16777216) + 11,
            281474976710656)
    return X / 281474976710656
}
function gauss(  u, v) {u = urand(); v = urand(); return sqrt(-2 * log(1 - u)) * cos(6.283185307 * v)}
