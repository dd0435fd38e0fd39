# Where the methods fail (issue 5): the θ-method's measured time-step limit against the
# thesis' bound (3.3), for θ = 0 and θ = ¼, per weight, h rule and level.
DATAFILES += $(DATA)/thesis_stability.tsv
FIGFILES  += $(FIGOUT)/thesis_stability.svg

# Not a file of the result store: in the paper profile it is data/paper's own (no store
# re-check; the runner keeps the rows its code still fingerprints).
$(DATA)/thesis_stability.tsv: $(BUILD)/thesis_stability
	$< --profile $(PROFILE) --out $@
	@touch $@  # a fully cached rerun leaves the file as it was

$(FIGOUT)/thesis_stability.svg: figures/thesis_stability.gp figures/style.gp $(DATA)/thesis_stability.tsv
