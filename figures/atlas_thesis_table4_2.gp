# Atlas of thesis Table 4.2 (see figures/atlas_truncation.gp).
table = '4_2'
load 'figures/atlas_truncation.gp'
