# Figure 4.10 (thesis §4.3): Δt = 0.5h², θ = 1/2, 1 (θ = 0 is unstable, Table 4.6).
load 'figures/style.gp'
f = datadir.'/thesis_table4_6.tsv'
thetas = '0.5 1'
eval triangle(0.12, 5e-4, 1.2, 2, 'slope 2')
load 'figures/thesis_heat.gp'
