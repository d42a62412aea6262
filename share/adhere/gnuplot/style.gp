# adhere's gnuplot style, loaded before every figure (after `reset`).
# A copy given with --gnuplot-style=FILE replaces it. adh_figure names the
# figure being drawn ("force", "profile", "contact") for per-figure tweaks.
# The tests check the PNG size against this line: keep it 900x600 or
# update tests/plots too.
set terminal pngcairo size 900,600 enhanced font "DejaVu Sans,11" linewidth 1
set encoding utf8
set grid lc rgb "#e5e5e5"
set border lw 1.2
set tics out nomirror
# keys sit outside the data (adhere places each); a light box, small type
set key box lc rgb "#bbbbbb" opaque Left reverse samplen 4 spacing 1.05 font ",9"
# dashes of the run's second branches and of the references (dt 2 is the
# short dash of unstable stretches)
set dashtype 11 (24,10)
set dashtype 12 (4,8)
set dashtype 13 (20,8,4,8)

# Colours: Paul Tol's "muted" scheme, told apart with every common colour
# vision deficiency (https://personal.sron.nl/~pault/). The run is in
# colour, the references (models, rigid spheres) in black and grey, each
# with its own dash pattern, so that no model shares a hue with a branch.
# Loading is bold (the paper draws it so); each unloading branch takes the
# next colour of adh_unload_colors and the next dash of adh_unload_dashes
# (past the last colour the dashes tell them apart); each profile position
# takes the next of adh_profile_colors. Unstable (static mode) stretches
# are dashed and thin.
adh_loading_color = "#332288"
adh_unload_colors = "#CC6677 #117733 #AA4499 #882255 #88CCEE #999933 #DDCC77"
adh_unload_dashes = "1 13"
adh_profile_colors = "#332288 #CC6677 #44AA99 #882255 #117733 #AA4499 #88CCEE #999933 #DDCC77 #000000"
adh_static_color = "#44AA99"
# the runs of a sweep (Figure 7's eps), light to dark: Tol's high-contrast
# scheme first, which greyscale keeps apart too
adh_sweep_colors = "#DDAA33 #BB5566 #004488 #117733 #AA4499 #88CCEE #332288"
# the contact line's node-by-node hops on loading, pale under the smoothed speed
adh_hop_color = "#b3aed6"
adh_loading_width = 2.5
adh_unloading_width = 1.8
adh_unstable_dash = 2
# The model curves past their load-controlled pull-off (only displacement
# control gets there: Figure 7's break) keep their dash, thin and grey.
adh_model_disp_color = "#999999"

set style line 1 lc rgb adh_loading_color lw adh_loading_width            # loading
set style line 2 lc rgb "#000000" lw 1 dt 1                               # rigid spheres, eq 22
set style line 3 lc rgb "#000000" lw 1.5 dt 11                            # JKR
set style line 4 lc rgb "#000000" lw 2 dt 12                              # DMT
set style line 5 lc rgb "#c8c8c8" lw 5 dt 1                               # undeformed sphere (a band)
set style line 6 lc rgb "#000000" lw 1.4 pt 7 ps 0.9                      # adhesion vs load
set style line 7 lc rgb "#888888" lw 0.8 dt 1                             # zero line
set style line 8 lc rgb "#b0b0b0" lw 4 dt 1                               # Maugis-Dugdale (a band under JKR)
set style line 9 lc rgb adh_static_color lw 1.8 dt 1                      # static equilibrium (--reference)
