# adhere's gnuplot style, loaded before every figure (after `reset`).
# A copy given with --gnuplot-style=FILE replaces it. adh_figure names the
# figure being drawn ("force", "profile", "contact") for per-figure tweaks.
# The tests check the PNG size against this line: keep it 900x600 or
# update tests/plots too.
set terminal pngcairo size 900,600 enhanced font "DejaVu Sans,11" linewidth 1
set encoding utf8
set grid lc rgb "#dddddd"
set border lw 1.2
set tics out nomirror
set key box opaque samplen 2.5 spacing 1.1 font ",10"

# Loading is bold (the paper draws it so); each unloading branch takes the
# next colour of adh_unload_colors, and each profile position the next of
# adh_profile_colors. Unstable (static mode) stretches are dashed and thin.
adh_loading_color = "#1f3f8f"
adh_unload_colors = "#c0392b #e67e22 #27ae60 #8e44ad #16a085 #d35400 #2c3e50 #b7950b #7f8c8d"
adh_profile_colors = "#1f3f8f #2e6fb7 #3aa0c8 #27ae60 #8bc34a #c9b600 #e67e22 #d35400 #c0392b #8e44ad"
adh_loading_width = 2.5
adh_unloading_width = 1.6
adh_unstable_dash = 2
# The model curves on force.png past their load-controlled pull-off (only
# displacement control gets there: Figure 7's break) are short-dashed.
adh_model_disp_dash = "- "

set style line 1 lc rgb adh_loading_color lw adh_loading_width            # loading
set style line 2 lc rgb "#000000" lw 1.2 dt 1                             # rigid spheres, eq 22
set style line 3 lc rgb "#2ca02c" lw 1.8 dt 1                             # JKR
set style line 4 lc rgb "#6a1b9a" lw 1.4 dt 4                             # DMT
set style line 5 lc rgb "#000000" lw 1.2 dt 3                             # undeformed sphere
set style line 6 lc rgb "#c0392b" lw 1.6 pt 7 ps 0.9                      # adhesion vs load
set style line 7 lc rgb "#888888" lw 1 dt 1                               # zero line
set style line 8 lc rgb "#e377c2" lw 0.9 dt 1                             # Maugis-Dugdale
set style line 9 lc rgb "#26a69a" lw 1.2 dt 1                             # static equilibrium (--reference)
