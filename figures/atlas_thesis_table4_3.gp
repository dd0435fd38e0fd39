# Atlas of thesis Table 4.3 (see figures/atlas_truncation.gp).
table = '4_3'
load 'figures/atlas_truncation.gp'
