# Figure 4.11 (thesis §4.3): Δt = 0.5h, θ = 1/2, 1.
load 'figures/style.gp'
# data_file (set by figures/store_reading.sh): the store file of one reading of the set-up.
f = exists('data_file') ? data_file : datadir.'/thesis_table4_7.tsv'
thetas = '0.5 1'
slopes = '2 1'  # Theorem 3.7 with m = 4 and the table's dt
P = 'tables/published/thesis_table4_7_long.tsv'
load 'figures/thesis_heat.gp'
