# Figure 4.9 (thesis §4.3): Δt = 0.0025h², θ = 0, 1/2, 1.
load 'figures/style.gp'
# data_file (set by figures/store_reading.sh): the store file of one reading of the set-up.
f = exists('data_file') ? data_file : datadir.'/thesis_table4_5.tsv'
thetas = '0 0.5 1'
slopes = '2 2 2'  # Theorem 3.7 with m = 4 and the table's dt
P = 'tables/published/thesis_table4_5_long.tsv'
load 'figures/thesis_heat.gp'
