/* gnuplot plots (plot.h). */
#include "tools/plot.h"

#include <stdio.h>
#include <stdlib.h>

int hx_gnuplot(const char *path, const char *script)
{
    if (system("command -v gnuplot >/dev/null 2>&1") != 0)
        return 1;
    FILE *f = fopen(path, "w");
    if (f == NULL)
        return -1;
    fputs(script, f);
    fclose(f);
    char command[4200];
    snprintf(command, sizeof command, "gnuplot '%s' >/dev/null 2>&1", path);
    return system(command) == 0 ? 0 : -1;
}

int hx_plot_rig(const char *csv, const char *prefix, const char *title, int a, int b,
                unsigned directions)
{
    int panels = 0;
    for (int k = 0; k < 6; ++k)
        panels += (directions >> k) & 1u;
    if (panels == 0)
        directions = 1u << a, panels = 1;
    static const char *const disp[6] = {"x", "y", "z", "ax", "ay", "az"};
    static const char *const load[6] = {"Fx", "Fy", "Fz", "Tx", "Ty", "Tz"};
    char script[8192];
    int n = snprintf(script, sizeof script,
        "set datafile separator ','\nset datafile columnheaders\n"
        "set terminal pngcairo size 900,800 font ',11'\n"
        "set grid\nunset key\n"
        "set output '%s_force_path.png'\n"
        "set title '%s: force path, %s against %s'\n"
        "set size ratio -1\nset xlabel '%s'\nset ylabel '%s'\n"
        "plot '%s' using %d:%d with lines lw 2\n"
        "set output '%s_deformation_path.png'\n"
        "set title '%s: deformation path, %s against %s'\n"
        "set xlabel '%s'\nset ylabel '%s'\n"
        "plot '%s' using %d:%d with lines lw 2\n"
        "set size noratio\n"
        "set terminal pngcairo size %d,%d font ',10'\n"
        "set output '%s_force_deformation.png'\n"
        "set multiplot layout %d,%d title '%s: force against deformation per direction'\n",
        prefix, title, load[b], load[a], load[a], load[b], csv, 14 + a, 14 + b,
        prefix, title, disp[b], disp[a], disp[a], disp[b], csv, 2 + a, 2 + b,
        panels > 3 ? 1400 : 480 * panels, panels > 3 ? 900 : 460, prefix, panels > 3 ? 2 : 1,
        panels > 3 ? 3 : panels, title);
    for (int k = 0; k < 6 && n > 0 && (size_t)n < sizeof script; ++k)
        if ((directions >> k) & 1u)
        n += snprintf(script + n, sizeof script - (size_t)n,
                      "set title '%s against %s'\nset xlabel '%s'\nset ylabel '%s'\n"
                      "plot '%s' using %d:%d with lines lw 2\n",
                      load[k], disp[k], disp[k], load[k], csv, 2 + k, 14 + k);
    if (n > 0 && (size_t)n < sizeof script)
        snprintf(script + n, sizeof script - (size_t)n, "unset multiplot\n");
    char path[4096];
    snprintf(path, sizeof path, "%s.gp", prefix);
    return hx_gnuplot(path, script);
}

int hx_plot_states(const char *csv, const char *prefix, const char *title, int first,
                   int nstates)
{
    char script[8192];
    int n = snprintf(script, sizeof script,
                     "set datafile separator ','\nset datafile columnheaders\n"
                     "set terminal pngcairo size 900,500 font ',11'\nset grid\nset key outside\n"
                     "set output '%s_states.png'\n"
                     "set title '%s: internal states along the path' noenhanced\n"
                     "set xlabel 't'\nset ylabel 'state (model units)'\nplot ",
                     prefix, title);
    for (int k = 0; k < nstates && n > 0 && (size_t)n < sizeof script; ++k)
        n += snprintf(script + n, sizeof script - (size_t)n,
                      "%s'%s' using 1:%d with lines lw 2 title columnheader(%d) noenhanced",
                      k ? ", " : "", csv, first + k, first + k);
    if (n > 0 && (size_t)n < sizeof script)
        snprintf(script + n, sizeof script - (size_t)n, "\n");
    char path[4096];
    snprintf(path, sizeof path, "%s_states.gp", prefix);
    return hx_gnuplot(path, script);
}
