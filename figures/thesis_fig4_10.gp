# Figure 4.10 (thesis §4.3): Δt = 0.5h², θ = 1/2, 1 (θ = 0 is unstable, Table 4.6).
load 'figures/style.gp'
# data_file (set by figures/store_reading.sh): the store file of one reading of the set-up.
f = exists('data_file') ? data_file : datadir.'/thesis_table4_6.tsv'
thetas = '0.5 1'
slopes = '2 2'  # Theorem 3.7 with m = 4 and the table's dt
P = 'tables/published/thesis_table4_6_long.tsv'
load 'figures/thesis_heat.gp'
