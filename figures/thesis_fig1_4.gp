# Thesis Figure 1.4: G for a distribution with an isolated group in Omega.
C = 'isolated'; T = 'Figure 1.4'
load 'figures/thesis_connectivity.gp'
