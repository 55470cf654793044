/* sepax benchmarks — a small SVG writer for "error against cost" plots.
 *
 * Both axes are logarithmic (costs and errors span decades); the axis range
 * is widened to whole decades around the data, with a tick and a grid line
 * per decade. Each engine is one colour; its Pareto front (the points that
 * no other point of the same engine beats on both time and error) is joined
 * by a line, so the best trade-off each engine offers reads at a glance.
 * Errors of 0 cannot sit on a log axis: they are drawn at the bottom edge. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scenes.h"

static const char *const colours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e"};

enum { W = 720, H = 480, ML = 80, MR = 170, MT = 40, MB = 60 };

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

static int plot_write(const char *path, const char *title, const char *xlabel, const char *ylabel,
                      const svg_point *pts, int n, const char *const *series_names,
                      int series_count, int pareto) {
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; ++i) {
        if (pts[i].x > 0) {
            if (pts[i].x < xmin) xmin = pts[i].x;
            if (pts[i].x > xmax) xmax = pts[i].x;
        }
        if (pts[i].y > 0) {
            if (pts[i].y < ymin) ymin = pts[i].y;
            if (pts[i].y > ymax) ymax = pts[i].y;
        }
    }
    if (!(xmin <= xmax)) xmin = xmax = 1.0;
    if (!(ymin <= ymax)) ymin = ymax = 1.0;
    double lx0 = floor(log10(xmin)), lx1 = ceil(log10(xmax));
    double ly0 = floor(log10(ymin)), ly1 = ceil(log10(ymax));
    if (lx1 <= lx0) lx1 = lx0 + 1;
    if (ly1 <= ly0) ly1 = ly0 + 1;
    const double px0 = ML, px1 = W - MR, py0 = H - MB, py1 = MT;

    fprintf(f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
            "font-family=\"sans-serif\" font-size=\"12\">\n",
            W, H);
    fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(f, "<text x=\"%d\" y=\"22\" font-size=\"14\">", ML);
    xml_text(f, title);
    fprintf(f, "</text>\n");
    for (double d = lx0; d <= lx1 + 1e-9; d += 1.0) {
        double x = map_log(pow(10.0, d), lx0, lx1, px0, px1);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", x,
                py0, x, py1);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%d</text>\n", x, py0 + 16,
                (int)d);
    }
    for (double d = ly0; d <= ly1 + 1e-9; d += 1.0) {
        double y = map_log(pow(10.0, d), ly0, ly1, py0, py1);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", px0,
                y, px1, y);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n", px0 - 6, y + 4,
                (int)d);
    }
    fprintf(f,
            "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
            "stroke=\"black\"/>\n",
            px0, py1, px1 - px0, py0 - py1);
    fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">", (px0 + px1) / 2, H - 18);
    xml_text(f, xlabel);
    fprintf(f, " (log)</text>\n");
    fprintf(f, "<text transform=\"translate(18 %.1f) rotate(-90)\" text-anchor=\"middle\">",
            (py0 + py1) / 2);
    xml_text(f, ylabel);
    fprintf(f, " (log)</text>\n");

    svg_point *tmp = malloc((size_t)(n > 0 ? n : 1) * sizeof *tmp);
    for (int s = 0; s < series_count; ++s) {
        const char *col = colours[s % 5];
        int m = 0;
        for (int i = 0; i < n; ++i)
            if (pts[i].series == s && pts[i].x > 0) tmp[m++] = pts[i];
        if (tmp && m > 0) {
            /* Pareto front: by increasing time, keep each point more accurate
             * than every faster one. */
            qsort(tmp, (size_t)m, sizeof *tmp, cmp_x);
            fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", col);
            double best = INFINITY;
            for (int i = 0; i < m; ++i) {
                double yv = tmp[i].y > 0 ? tmp[i].y : pow(10.0, ly0);
                if (!pareto || yv < best) {
                    best = yv;
                    fprintf(f, "%.1f,%.1f ", map_log(tmp[i].x, lx0, lx1, px0, px1),
                            map_log(yv, ly0, ly1, py0, py1));
                }
            }
            fprintf(f, "\"/>\n");
            for (int i = 0; i < m; ++i) {
                double yv = tmp[i].y > 0 ? tmp[i].y : pow(10.0, ly0);
                fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"%s\"><title>",
                        map_log(tmp[i].x, lx0, lx1, px0, px1), map_log(yv, ly0, ly1, py0, py1),
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
        fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"12\" fill=\"%s\"/>\n",
                W - MR + 16, MT + 20 * s, col);
        fprintf(f, "<text x=\"%d\" y=\"%d\">", W - MR + 34, MT + 20 * s + 11);
        xml_text(f, series_names[s]);
        fprintf(f, "</text>\n");
    }
    if (pareto) {
        fprintf(f, "<text x=\"%d\" y=\"%d\" font-size=\"10\">line: Pareto front</text>\n",
                W - MR + 16, MT + 20 * series_count + 12);
    }
    free(tmp);
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
