# Lo que un resultado dice de sí mismo: sus avisos y cómo se estimó su
# precisión, en español (inglés en ../en/results.ftl, con los mismos
# identificadores y argumentos).
