# Thesis Figure 4.3: interpolant errors against h (Table 4.1), h = (3.1^3 2^-10 dx)^(1/3).
f = datadir.'/thesis_table4_1.tsv'; OP = 'interp'
W = 'quadratic_spike cubic_bspline quintic_bspline'
L = 'quadr.spike cubic-B quintic-B'
S = '2'; T = 'Figure 4.3 (thesis): Π_h, h = (3.1^3·2^{-10}Δx)^{1/3}'
P = 'tables/published/thesis_table4_1_long.tsv'
load 'figures/thesis_errors.gp'
