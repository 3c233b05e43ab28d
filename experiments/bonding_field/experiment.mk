# The bonding field (beyond the paper): capture, escape and debond maps over (v0, beta0), (v0, eps_a).
$(eval $(call driver_and_plot,bonding_field,bonding_field.png bonding_field.svg))
