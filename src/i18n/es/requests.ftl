# Las peticiones de cada tipo: lo que debe ser un campo de un mecanismo,
# una leva, un rotor, un tren de engranajes…, en español (inglés en
# ../en/requests.ftl, con los mismos identificadores y argumentos).
