# The "how to choose settings" table of bench/README.md, from a run's
# scenes.csv (make bench-scenes writes build/bench/scenes.csv):
#   awk -F, -f scripts/choose_settings.awk build/bench/scenes.csv
# (-v default='dt=1/60 sub=5 vel=3 pos=1' names sepax's default configuration
# as the bench writes it, if the defaults change.)
# For each scene in which sepax ran several configurations with an error
# metric: sepax's best error, and the cheapest sepax configuration (ms per
# 1/60 s frame) whose error is within 10 % of that best; beside it the
# default configuration's error and cost. Errors are deterministic; the costs
# are that run's, so the choice between configurations of similar cost can
# move from run to run.
BEGIN { if (default == "") default = "dt=1/60 sub=5 vel=3 pos=1" }
NR == 1 { next }
$2 != "sepax" || $8 == "none" || $8 == "cost_ratio" || $1 ~ /_workers$/ { next }
{
    s = $1; n = ++count[s]
    if (n == 1) { order[++scenes] = s; metric[s] = $8 }
    cfg[s, n] = $3; ms[s, n] = $7 + 0; err[s, n] = $9 + 0
    if (n == 1 || err[s, n] < best[s]) best[s] = err[s, n]
}
END {
    print "| scene | error metric | sepax's best error | cheapest within 10 % of it | ms per frame, error | the defaults (" default "): ms per frame, error |"
    print "| --- | --- | --- | --- | --- | --- |"
    for (i = 1; i <= scenes; ++i) {
        s = order[i]
        if (count[s] < 2) continue
        pick = 0; def = 0
        for (n = 1; n <= count[s]; ++n) {
            if (err[s, n] <= 1.1 * best[s] && (!pick || ms[s, n] < ms[s, pick])) pick = n
            if (cfg[s, n] == default) def = n
        }
        m = metric[s]; gsub(/\|/, "\\|", m)
        printf "| %s | %s | %.3g | %s | %.3g ms, %.3g | %s |\n", s, m, best[s], cfg[s, pick],
               ms[s, pick], err[s, pick],
               def ? sprintf("%.3g ms, %.3g", ms[s, def], err[s, def]) : "-"
    }
}
