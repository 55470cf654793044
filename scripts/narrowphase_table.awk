# Turns build/bench/narrowphase.csv (written by `make bench`) into the
# markdown table the README's Figures section shows: for each pair type, the
# time of sx_collide as a ratio against each peer's manifold routine measured
# in the same run (< 1: sepax faster), Box2D v3's both as its users call it
# (answer in A's frame) and moved to world space as sx_collide answers; how
# much cheaper the yes/no test is; and the largest depth error of each engine
# against the long-double reference. Ratios, not nanoseconds: the machine is
# shared and noisy.
#
#   awk -F, -f scripts/narrowphase_table.awk build/bench/narrowphase.csv
NR == 1 { next }
{
    eng = $2 ~ /^sepax/ ? "sepax" : $2  # sepax-double in the double build
    key = $1 SUBSEP eng SUBSEP $3
    ns[key] = $4
    err[key] = $5
    if (!($1 in seen)) { seen[$1] = 1; order[++npairs] = $1 }
}
function ratio(a, b) { return (a == "" || b == "" || b == 0) ? "–" : sprintf("%.2f", a / b) }
function e(x) { return x == "" ? "–" : sprintf("%.1e", x) }
END {
    print "| pair | collide ns | / Box2D v3 | / v3 + world | / Box2D 2.4 | / Chipmunk | collide / overlap | sepax max err m | Box2D v3 max err m | Box2D 2.4 max err m | Chipmunk max err m |"
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (i = 1; i <= npairs; ++i) {
        p = order[i]
        c = ns[p, "sepax", "collide"]
        printf "| %s | %.0f | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", p, c,
               ratio(c, ns[p, "box2d3", "collide"]), ratio(c, ns[p, "box2d3", "collide_world"]),
               ratio(c, ns[p, "box2d", "collide"]), ratio(c, ns[p, "chipmunk", "collide"]),
               ratio(c, ns[p, "sepax", "overlap"]), e(err[p, "sepax", "collide"]),
               e(err[p, "box2d3", "collide"]), e(err[p, "box2d", "collide"]),
               e(err[p, "chipmunk", "collide"])
    }
}
