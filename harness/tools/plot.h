/* PNG plots through gnuplot (the field's plotting tool), when it is installed. */
#ifndef HX_TOOLS_PLOT_H
#define HX_TOOLS_PLOT_H

/* Writes script into path and runs gnuplot on it. Returns 0 when gnuplot
 * ran, 1 when it is not installed, -1 when it failed. */
int hx_gnuplot(const char *path, const char *script);

/* The rig's plots from its CSV: PREFIX_force_path.png (the force in the
 * plane of the path), PREFIX_deformation_path.png, PREFIX_force_deformation.png
 * (force against deformation for the directions in the mask that move or
 * carry force). a and b: the plane's directions. */
int hx_plot_rig(const char *csv, const char *prefix, const char *title, int a, int b,
                unsigned directions);

/* PREFIX_states.png: a Force_StateEqn rig's states against time, from its
 * CSV (the states from column first, one panel for all). */
int hx_plot_states(const char *csv, const char *prefix, const char *title, int first,
                   int nstates);

#endif
