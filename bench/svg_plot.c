/* sepax benchmarks — a small SVG writer for the plots a reader looks at
 * first: "error against cost" scatter plots, scaling curves and bar charts.
 *
 * Scatter and curves: both axes are logarithmic (costs and errors span
 * decades); the axis range is widened to whole decades around the data, with
 * a tick and a grid line per decade. Each engine is one colour, the same in
 * every plot of the run; its Pareto front (the points that no other point of
 * the same engine beats on both time and error) is joined by a line, so the
 * best trade-off each engine offers reads at a glance. Errors of 0 cannot sit
 * on a log axis: they are drawn at the bottom edge. Each point of a scatter
 * plot carries its configuration as a small label, placed beside the point
 * where it covers the fewest labels and points already drawn (a greedy
 * choice among eight positions: crowded plots may still overlap).
 *
 * Bars are horizontal, one row per engine with its name at the left and its
 * value at the bar's end, on a linear axis from 0: ratios between engines
 * read as lengths. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenes.h"

/* Tableau's ten colours, distinct for the six engines of a run. */
static const char *const colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e",
                                      "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
enum { NCOLOURS = (int)(sizeof colours / sizeof colours[0]) };

static const char *colour(int series) { return colours[series % NCOLOURS]; }

enum { W = 960, H = 600, ML = 80, MR = 190, MT = 40, MB = 60 };

/* Point labels: font size, and the width of a character as a fraction of it
 * (sans-serif digits and lower case average about 0.55 em). */
enum { LABEL_FS = 9 };
static const double LABEL_EM = 0.56;

/* The suffix the sweeps give an engine's default configuration. */
static const char DEFAULT_SUFFIX[] = " (default)";

static double map_log(double v, double lo, double hi, double a, double b) {
    double t = (log10(v) - lo) / (hi - lo);
    return a + t * (b - a);
}

static int cmp_x(const void *pa, const void *pb) {
    const svg_point *a = pa, *b = pb;
    return (a->x > b->x) - (a->x < b->x);
}

static void xml_text(FILE *f, const char *s) {
    for (; *s; ++s) {
        if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else if (*s == '&')
            fputs("&amp;", f);
        else
            fputc(*s, f);
    }
}

static int is_default(const char *label) {
    size_t n = label ? strlen(label) : 0, k = sizeof DEFAULT_SUFFIX - 1;
    return n >= k && strcmp(label + n - k, DEFAULT_SUFFIX) == 0;
}

/* ---- label placement ---------------------------------------------------- */

typedef struct rect {
    double x0, y0, x1, y1;
} rect;

static double overlap_area(rect a, rect b) {
    double w = fmin(a.x1, b.x1) - fmax(a.x0, b.x0), h = fmin(a.y1, b.y1) - fmax(a.y0, b.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
}

/* Chooses where the label of the point at (px, py) goes: the candidate
 * position that overlaps the rectangles taken so far least, and stays inside
 * the frame; adds its rectangle to `taken`. Candidates: beside the point
 * first, then farther out (drawn with a leader line). Returns the text's
 * anchor point, its alignment (0 start, 1 end, 2 middle) and whether it
 * needs a leader. */
static void place_label(double px, double py, double width, rect frame, rect *taken, int *ntaken,
                        double *tx, double *ty, int *align, int *leader) {
    /* text anchor offsets and alignment: right, right-up, right-down, left,
     * left-up, left-down, above, below; then the same sides 2-3 lines away */
    static const double cand[][3] = {
        {7, 3, 0},   {6, -6, 0}, {6, 12, 0},   {-7, 3, 1},  {-6, -6, 1},   {-6, 12, 1},
        {0, -9, 2},  {0, 17, 2}, {10, -18, 0}, {10, 24, 0}, {-10, -18, 1}, {-10, 24, 1},
        {0, -22, 2}, {0, 30, 2}, {14, -30, 0}, {14, 36, 0}, {-14, -30, 1}, {-14, 36, 1}};
    enum { NEAR = 8, NCAND = (int)(sizeof cand / sizeof cand[0]) };
    const double h = LABEL_FS;
    double best = INFINITY;
    rect best_r = {0, 0, 0, 0};
    for (int k = 0; k < NCAND; ++k) {
        double ax = px + cand[k][0], ay = py + cand[k][1];
        int mode = (int)cand[k][2];
        double x0 = mode == 0 ? ax : mode == 1 ? ax - width : ax - width / 2;
        rect r = {x0, ay - h + 1, x0 + width, ay + 2};
        /* a far place must beat a near one clearly: a leader line costs a
         * little legibility too */
        double cost = k < NEAR ? 0.0 : 0.1 * width * h;
        for (int i = 0; i < *ntaken; ++i)
            cost += overlap_area(r, taken[i]);
        /* out of the frame costs as much as covering a whole label */
        if (r.x0 < frame.x0 || r.x1 > frame.x1 || r.y0 < frame.y0 || r.y1 > frame.y1)
            cost += width * h + 1.0;
        if (cost < best) {
            best = cost;
            best_r = r;
            *tx = ax;
            *ty = ay;
            *align = mode;
            *leader = k >= NEAR;
        }
        if (cost == 0.0) break;
    }
    taken[(*ntaken)++] = best_r;
}

/* ---- scatter plots and curves ------------------------------------------- */

typedef struct axes {
    double lx0, lx1, ly0, ly1, px0, px1, py0, py1;
} axes;

static double ax_x(const axes *a, double v) { return map_log(v, a->lx0, a->lx1, a->px0, a->px1); }
static double ax_y(const axes *a, double v) {
    /* errors of 0 sit on the bottom edge */
    return map_log(v > 0 ? v : pow(10.0, a->ly0), a->ly0, a->ly1, a->py0, a->py1);
}

static axes make_axes(const svg_point *pts, int n) {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; ++i) {
        if (pts[i].x > 0) {
            xmin = fmin(xmin, pts[i].x);
            xmax = fmax(xmax, pts[i].x);
        }
        if (pts[i].y > 0) {
            ymin = fmin(ymin, pts[i].y);
            ymax = fmax(ymax, pts[i].y);
        }
    }
    if (!(xmin <= xmax)) xmin = xmax = 1.0;
    if (!(ymin <= ymax)) ymin = ymax = 1.0;
    axes a;
    a.lx0 = floor(log10(xmin));
    a.lx1 = ceil(log10(xmax));
    a.ly0 = floor(log10(ymin));
    a.ly1 = ceil(log10(ymax));
    if (a.lx1 <= a.lx0) a.lx1 = a.lx0 + 1;
    if (a.ly1 <= a.ly0) a.ly1 = a.ly0 + 1;
    a.px0 = ML;
    a.px1 = W - MR;
    a.py0 = H - MB;
    a.py1 = MT;
    return a;
}

static void svg_open(FILE *f, int w, int h, const char *title, double title_x) {
    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "font-family=\"sans-serif\" font-size=\"12\">\n",
            w, h);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(f, "<text x=\"%.0f\" y=\"22\" font-size=\"14\">", title_x);
    xml_text(f, title);
    fprintf(f, "</text>\n");
}

static void draw_log_frame(FILE *f, const axes *a, const char *xlabel, const char *ylabel) {
    for (double d = a->lx0; d <= a->lx1 + 1e-9; d += 1.0) {
        double x = ax_x(a, pow(10.0, d));
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x,
                a->py0, x, a->py1);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%d</text>\n", x,
                a->py0 + 16, (int)d);
    }
    for (double d = a->ly0; d <= a->ly1 + 1e-9; d += 1.0) {
        double y = ax_y(a, pow(10.0, d));
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
                a->px0, y, a->px1, y);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", a->px0 - 6,
                y + 4, (int)d);
    }
    fprintf(f,
            "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
            "stroke=\"black\"/>\n",
            a->px0, a->py1, a->px1 - a->px0, a->py0 - a->py1);
    fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">", (a->px0 + a->px1) / 2, H - 18);
    xml_text(f, xlabel);
    fprintf(f, " (log)</text>\n");
    fprintf(f, "<text transform=\"translate(18 %.1f) rotate(-90)\" text-anchor=\"middle\">",
            (a->py0 + a->py1) / 2);
    xml_text(f, ylabel);
    fprintf(f, " (log)</text>\n");
}

/* The point labels of a scatter plot, after every marker is drawn (so that
 * placement knows where all the points are): each engine's default
 * configuration first, then the others. */
static void draw_labels(FILE *f, const axes *a, const svg_point *pts, int n) {
    rect *taken = malloc((size_t)(2 * n + 1) * sizeof *taken);
    if (!taken) return;
    int nt = 0;
    for (int i = 0; i < n; ++i) {
        if (!(pts[i].x > 0)) continue;
        double x = ax_x(a, pts[i].x), y = ax_y(a, pts[i].y);
        rect r = {x - 4, y - 4, x + 4, y + 4};
        taken[nt++] = r;
    }
    const rect frame = {a->px0 + 1, a->py1 + 1, a->px1 - 1, a->py0 - 1};
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = 0; i < n; ++i) {
            const char *label = pts[i].label;
            if (!(pts[i].x > 0) || !label || !*label || is_default(label) != (pass == 0)) continue;
            double x = ax_x(a, pts[i].x), y = ax_y(a, pts[i].y), tx = x, ty = y;
            int align = 0, leader = 0;
            place_label(x, y, LABEL_EM * LABEL_FS * (double)strlen(label), frame, taken, &nt, &tx,
                        &ty, &align, &leader);
            if (leader)
                fprintf(f,
                        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                        "stroke-width=\"0.6\"/>\n",
                        x, y, tx, ty - (ty > y ? LABEL_FS : 0) + (ty > y ? 0 : 2),
                        colour(pts[i].series));
            fprintf(f,
                    "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%d\" fill=\"%s\" text-anchor=\"%s\" "
                    "stroke=\"white\" stroke-width=\"2.5\" paint-order=\"stroke\">",
                    tx, ty, LABEL_FS, colour(pts[i].series),
                    align == 0   ? "start"
                    : align == 1 ? "end"
                                 : "middle");
            xml_text(f, label);
            fprintf(f, "</text>\n");
        }
    }
    free(taken);
}

static int plot_write(const char *path, const char *title, const char *xlabel, const char *ylabel,
                      const svg_point *pts, int n, const char *const *series_names,
                      int series_count, int pareto) {
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    const axes a = make_axes(pts, n);
    svg_open(f, W, H, title, ML);
    draw_log_frame(f, &a, xlabel, ylabel);

    svg_point *tmp = malloc((size_t)(n > 0 ? n : 1) * sizeof *tmp);
    int legend = 0;
    for (int s = 0; s < series_count; ++s) {
        const char *col = colour(s);
        int m = 0;
        for (int i = 0; tmp && i < n; ++i)
            if (pts[i].series == s && pts[i].x > 0) tmp[m++] = pts[i];
        if (m > 0) {
            /* Pareto front: by increasing time, keep each point more accurate
             * than every faster one. */
            qsort(tmp, (size_t)m, sizeof *tmp, cmp_x);
            fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
            double best = INFINITY;
            for (int i = 0; i < m; ++i) {
                double yv = tmp[i].y > 0 ? tmp[i].y : pow(10.0, a.ly0);
                if (!pareto || yv < best) {
                    best = yv;
                    fprintf(f, "%.1f,%.1f ", ax_x(&a, tmp[i].x), ax_y(&a, tmp[i].y));
                }
            }
            fprintf(f, "\"/>\n");
            for (int i = 0; i < m; ++i) {
                const double cx = ax_x(&a, tmp[i].x), cy = ax_y(&a, tmp[i].y);
                if (pareto && is_default(tmp[i].label))
                    fprintf(f,
                            "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"8\" fill=\"none\" stroke=\"%s\" "
                            "stroke-width=\"2\"/>\n",
                            cx, cy, col);
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"><title>", cx, cy,
                        col);
                xml_text(f, series_names[s]);
                fprintf(f, " ");
                xml_text(f, tmp[i].label ? tmp[i].label : "");
                if (pareto)
                    fprintf(f, ": %.4g ms, %.4g</title></circle>\n", tmp[i].x, tmp[i].y);
                else
                    fprintf(f, ": %.4g, %.4g</title></circle>\n", tmp[i].x, tmp[i].y);
            }
        }
        if (m == 0) continue; /* an engine without points has no legend entry */
        fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"12\" fill=\"%s\"/>\n",
                W - MR + 16, MT + 20 * legend, col);
        fprintf(f, "<text x=\"%d\" y=\"%d\">", W - MR + 34, MT + 20 * legend + 11);
        xml_text(f, series_names[s]);
        fprintf(f, "</text>\n");
        ++legend;
    }
    free(tmp);
    if (pareto) {
        draw_labels(f, &a, pts, n);
        const int y0 = MT + 20 * legend + 12;
        fprintf(f, "<text x=\"%d\" y=\"%d\" font-size=\"10\">line: Pareto front</text>\n",
                W - MR + 16, y0);
        fprintf(f,
                "<circle cx=\"%d\" cy=\"%d\" r=\"6\" fill=\"none\" stroke=\"black\" "
                "stroke-width=\"1.5\"/>\n",
                W - MR + 22, y0 + 14);
        fprintf(f, "<text x=\"%d\" y=\"%d\" font-size=\"10\">default configuration</text>\n",
                W - MR + 34, y0 + 18);
        fprintf(f, "<text x=\"%d\" y=\"%d\" font-size=\"10\">labels: configuration</text>\n",
                W - MR + 16, y0 + 38);
    }
    fprintf(f, "</svg>\n");
    return fclose(f) == 0;
}

int svg_plot_write(const char *path, const char *title, const char *xlabel, const char *ylabel,
                   const svg_point *pts, int n, const char *const *series_names, int series_count) {
    return plot_write(path, title, xlabel, ylabel, pts, n, series_names, series_count, 1);
}

int svg_plot_write_lines(const char *path, const char *title, const char *xlabel,
                         const char *ylabel, const svg_point *pts, int n,
                         const char *const *series_names, int series_count) {
    return plot_write(path, title, xlabel, ylabel, pts, n, series_names, series_count, 0);
}

/* ---- bar charts ---------------------------------------------------------- */

/* The smallest 1, 2 or 5 x 10^k at or above v / 5: about five ticks. */
static double tick_step(double v) {
    double raw = v / 5.0, p = pow(10.0, floor(log10(raw))), m = raw / p;
    return p * (m <= 1.0 ? 1.0 : m <= 2.0 ? 2.0 : m <= 5.0 ? 5.0 : 10.0);
}

int svg_bars_write(const char *path, const char *title, const char *xlabel,
                   const char *const *group_names, int group_count, const char *const *series_names,
                   int series_count, const double *values) {
    enum { BW = 720, BML = 130, BMR = 90, ROW = 20, BAR = 14, GROUP_HEAD = 24, BMB = 50 };
    double vmax = 0.0;
    for (int i = 0; i < group_count * series_count; ++i)
        if (values[i] > vmax) vmax = values[i];
    if (!(vmax > 0.0)) vmax = 1.0;
    const double step = tick_step(vmax), top = ceil(vmax / step) * step;
    const double px0 = BML, px1 = BW - BMR;
    const int height = MT + group_count * (GROUP_HEAD + series_count * ROW) + BMB;
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    svg_open(f, BW, height, title, 16);
    const double py0 = MT, py1 = height - BMB + 6;
    for (double t = 0.0; t <= top + 1e-9 * top; t += step) {
        double x = px0 + t / top * (px1 - px0);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x,
                py0, x, py1);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%g</text>\n", x, py1 + 16,
                t);
    }
    fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">", (px0 + px1) / 2, height - 10);
    xml_text(f, xlabel);
    fprintf(f, "</text>\n");
    double y = MT;
    for (int g = 0; g < group_count; ++g) {
        if (group_count > 1 || (group_names[g] && *group_names[g])) {
            fprintf(f,
                    "<text x=\"16\" y=\"%.1f\" font-weight=\"bold\" stroke=\"white\" "
                    "stroke-width=\"3\" paint-order=\"stroke\">",
                    y + 16);
            xml_text(f, group_names[g]);
            fprintf(f, "</text>\n");
        }
        y += GROUP_HEAD;
        /* the zero line, under the group's bars only: group headings cross it */
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"black\"/>\n",
                px0, y, px0, y + series_count * ROW);
        for (int s = 0; s < series_count; ++s, y += ROW) {
            const double v = values[g * series_count + s];
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">", px0 - 8, y + 12);
            xml_text(f, series_names[s]);
            fprintf(f, "</text>\n");
            if (!(v > 0.0)) {
                fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" fill=\"#888\">not run</text>\n", px0 + 6,
                        y + 12);
                continue;
            }
            const double w = v / top * (px1 - px0);
            fprintf(f,
                    "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%d\" fill=\"%s\"><title>",
                    px0, y + (ROW - BAR) / 2.0, w, BAR, colour(s));
            xml_text(f, series_names[s]);
            fprintf(f, ": %.4g</title></rect>\n", v);
            /* two or three significant digits, without an exponent */
            const int decimals = v >= 100.0 ? 0 : v >= 10.0 ? 1 : v >= 1.0 ? 2 : v >= 0.1 ? 3 : 4;
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%.*f</text>\n", px0 + w + 5, y + 12, decimals,
                    v);
        }
    }
    fprintf(f, "</svg>\n");
    return fclose(f) == 0;
}
