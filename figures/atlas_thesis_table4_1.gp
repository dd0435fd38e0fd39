# Atlas of thesis Table 4.1 (see figures/atlas_truncation.gp).
table = '4_1'
load 'figures/atlas_truncation.gp'
