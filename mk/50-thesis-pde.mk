# Thesis §4.2–4.3 (issue 5): the discrete Poisson and heat problems, Figures 4.8–4.11,
# Tables 4.4–4.7, each reproduced rate beside the published one (rate_table).  The data and
# rate rules are the registry's (build/studies.mk, groups poisson and heat): one run of
# thesis_heat per table and h rule, which also writes the rows of the series that never blew
# up (…_finite.tsv), the rate table's input.
FIGFILES  += $(FIGOUT)/thesis_heat_readings.svg

$(FIGOUT)/thesis_heat_readings.svg: figures/thesis_heat_readings.gp figures/style.gp \
    $(foreach f,$(STUDY_FILES_heat),$(DATA)/$(f).tsv)
