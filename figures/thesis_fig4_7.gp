# Thesis Figure 4.7: Laplacian errors against h (Table 4.3).
f = datadir.'/thesis_table4_3.tsv'; OP = 'lap'
W = 'quartic_polynomial piecewise_cubic_polynomial piecewise_quintic_polynomial'
L = 'quartic pw-cubic pw-quintic'
S = '2'; T = 'Figure 4.7 (thesis): Δ_h, h = (3.1^4·2^{-10}Δx)^{1/4} (printed) and 3.1·2^{-3.75}Δx^{1/4} (scaled)'
P = 'tables/published/thesis_table4_3_long.tsv'
load 'figures/thesis_errors.gp'
