# Thesis Figure 1.3: G for a distribution satisfying the h-connectivity.
C = 'connected'; T = 'Figure 1.3'
load 'figures/thesis_connectivity.gp'
