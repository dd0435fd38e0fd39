# Figure 4.9 (thesis §4.3): Δt = 0.0025h², θ = 0, 1/2, 1.
load 'figures/style.gp'
f = datadir.'/thesis_table4_5.tsv'
thetas = '0 0.5 1'
eval triangle(0.12, 2e-3, 1.2, 2, 'slope 2')
load 'figures/thesis_heat.gp'
