# The kinds' requests: what a field of a mechanism, a cam, a rotor, a gear
# train… must be, in English (Spanish in ../es/requests.ftl, same ids and
# arguments).
