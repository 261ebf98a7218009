# What a result says about itself: its warnings and how its accuracy was
# estimated, in English (Spanish in ../es/results.ftl, same ids and
# arguments).
