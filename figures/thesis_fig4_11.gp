# Figure 4.11 (thesis §4.3): Δt = 0.5h, θ = 1/2, 1.
load 'figures/style.gp'
f = datadir.'/thesis_table4_7.tsv'
thetas = '0.5 1'
eval triangle(0.12, 5e-4, 1.2, 2, 'slope 2')
eval triangle(0.12, 3e-2, 1.2, 1, 'slope 1')
load 'figures/thesis_heat.gp'
