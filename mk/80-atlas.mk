# The atlas (issue 8): accuracy against cost for each study, from the times and pair counts
# the studies' own runs recorded (no separate timing).  One atlas + reading per study:
#   data/<profile>/atlas_<study>.tsv          rows (task, configuration, level, error, time, pairs)
#   data/<profile>/atlas_<study>_reading.tsv  per target error the cheapest configuration seen
ATLAS_STUDIES := imoto $(STUDIES_truncation) poisson heat
DATAFILES += $(foreach s,$(ATLAS_STUDIES),$(DATA)/atlas_$(s).tsv $(DATA)/atlas_$(s)_reading.tsv)
FIGFILES  += $(foreach s,$(ATLAS_STUDIES),$(FIGOUT)/atlas_$(s).svg)

atlas_out = --out $(DATA)/atlas_$(1).tsv --reading $(DATA)/atlas_$(1)_reading.tsv

$(DATA)/atlas_imoto.tsv: $(BUILD)/atlas $(DATA)/imoto_fig5_table1.tsv
	$< --study imoto --data $(DATA)/imoto_fig5_table1.tsv --task operator --config weight,m \
	  --time time_s --pairs pairs \
	  --time-note "wall time of the whole (level$(,) m) unit: the nine weights and three operators share one fused pass" \
	  --pairs-note "neighbour pairs (i$(,)j) of the level at h(m): the same for every weight of the unit" \
	  $(call atlas_out,imoto)

# Truncation tables: time = the fused pass of the (h reading, volumes, level) slice, shared by
# every weight, operator and case of the slice, plus the Voronoi volumes where used.
ATLAS_TRUNC := $(foreach s,$(STUDIES_truncation),$(DATA)/atlas_$(s).tsv)
$(ATLAS_TRUNC): $(DATA)/atlas_thesis_table4_%.tsv: $(BUILD)/atlas $(DATA)/thesis_table4_%.tsv
	$< --study thesis_table4_$* --data $(DATA)/thesis_table4_$*.tsv --task operator,function \
	  --config volumes,h_reading,weight --time time_s+voronoi_s --pairs pairs \
	  --time-note "fused pass of the (h reading$(,) volumes$(,) level) slice (all weights$(,) operators$(,) cases at once) + Voronoi volumes of the level (0 for uniform)" \
	  --pairs-note "neighbour pairs of the level at the slice's h" \
	  $(call atlas_out,thesis_table4_$*)

$(DATA)/atlas_poisson.tsv: $(BUILD)/atlas $(DATA)/thesis_table4_4.tsv
	$< --study poisson --data $(DATA)/thesis_table4_4.tsv --config h_rule,weight \
	  --time seconds --pairs nnz \
	  --time-note "assembly + CG solve of one (h rule$(,) weight$(,) level) problem" \
	  --pairs-note "nonzeros of the assembled matrix (pairs i$(,)j within h)" \
	  $(call atlas_out,poisson)

HEAT_DATA := $(foreach s,$(STUDIES_heat),$(DATA)/$(s).tsv)
$(DATA)/atlas_heat.tsv: $(BUILD)/atlas $(HEAT_DATA)
	$< --study heat --data $(subst $(eval) ,$(,),$(strip $(HEAT_DATA))) \
	  --config weight,theta,meta:dt_nominal --time seconds --filter blew_up=no \
	  --time-note "all K time steps of one (weight$(,) theta$(,) dt rule$(,) level) run; series that blew up are left out" \
	  $(call atlas_out,heat)

# The reading is written by the same run as the atlas.
$(foreach s,$(ATLAS_STUDIES),$(DATA)/atlas_$(s)_reading.tsv): $(DATA)/atlas_%_reading.tsv: $(DATA)/atlas_%.tsv ;

$(FIGOUT)/atlas_imoto.svg: figures/atlas_imoto.gp figures/style.gp $(DATA)/atlas_imoto.tsv
$(foreach s,$(STUDIES_truncation),$(FIGOUT)/atlas_$(s).svg): $(FIGOUT)/atlas_thesis_table4_%.svg: figures/atlas_thesis_table4_%.gp figures/atlas_truncation.gp figures/style.gp $(DATA)/atlas_thesis_table4_%.tsv
$(FIGOUT)/atlas_poisson.svg: figures/atlas_poisson.gp figures/style.gp $(DATA)/atlas_poisson.tsv
$(FIGOUT)/atlas_heat.svg: figures/atlas_heat.gp figures/style.gp $(DATA)/atlas_heat.tsv
