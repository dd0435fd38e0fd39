# Thesis Figure 4.5: interpolant errors against h (Table 4.2), h = (3.1^3 2^-10 dx)^(1/5) printed.
f = datadir.'/thesis_table4_2.tsv'; OP = 'interp'
W = 'cubic_bspline quintic_bspline quadratic_spike cubic_spike'
L = 'cubic-B quintic-B quadr.spike cubic-spike'
SW = '1 4'
S = '2 4'; T = 'Figure 4.5 (thesis): Π_h, h = (3.1^3·2^{-10}Δx)^{1/5} (printed) and 3.1·2^{-4}Δx^{1/5} (scaled)'
P = 'tables/published/thesis_table4_2_long.tsv'
load 'figures/thesis_errors.gp'
