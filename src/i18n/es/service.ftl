# Los mensajes de mechdyn en español: cada texto que lee una persona.
# Cada mensaje tiene su inglés en ../en/service.ftl con los mismos argumentos
# (src/i18n/tests.rs falla si no).

## Documentos de problema: títulos

problem-malformed-json = El cuerpo no es JSON válido
problem-unsupported-media-type = Tipo de contenido no admitido
problem-payload-too-large = Cuerpo de la petición demasiado grande
problem-invalid-request = La petición no es un problema válido
problem-invalid-query = Parámetros de consulta no válidos
problem-invalid-table = La tabla CSV no es válida
problem-job-not-found = Trabajo no encontrado
problem-not-found = No encontrado
problem-template-not-found = Plantilla no encontrada
problem-conflict = El nombre ya existe
problem-in-progress = Se está respondiendo la misma petición
problem-interrupted = El trabajo se interrumpió
problem-job-not-done = El trabajo no tiene resultado
problem-no-such-part = El resultado no tiene esa parte
problem-no-such-plot = El trabajo no tiene esa gráfica
problem-no-such-file = El trabajo no tiene ese fichero
problem-no-such-solution = El trabajo no tiene solución desarrollada
problem-method-not-allowed = Método no permitido
problem-compute-budget = El trabajo agotó su tiempo de cálculo
problem-result-too-large = El resultado sería demasiado grande
problem-saturated = El servicio está saturado
problem-storage-full = El almacenamiento del servicio está lleno
problem-database-unavailable = La base de datos no está disponible
problem-unauthorized = Falta el token de portador o es incorrecto
problem-request-timeout = El cuerpo de la petición no llegó a tiempo
problem-length-required = Se necesita la longitud del cuerpo
problem-internal = Error interno del servidor
problem-job-memory = El trabajo agotó su memoria
problem-compute-failed = Falló el cálculo del trabajo

## Documentos de problema: detalles

detail-malformed-json = el cuerpo no es JSON válido: { $why }
detail-unsupported-media-type = el tipo de contenido debe ser application/json
detail-unsupported-table = el tipo de contenido debe ser text/csv o application/json
detail-payload-too-large = el cuerpo supera el límite de { $limit } bytes
detail-invalid =
    { $count ->
        [one] 1 campo no válido
       *[other] { $count } campos no válidos
    }
detail-bad-query = parámetros de consulta no válidos
detail-bad-table =
    { $count ->
        [one] 1 error en la tabla CSV
       *[other] { $count } errores en la tabla CSV
    }
detail-not-found = no hay ningún trabajo con id '{ $id }'
detail-no-part = el trabajo '{ $id }' no tiene ninguna parte de su resultado en '{ $pointer }'
detail-no-plot = el trabajo '{ $id }' no tiene la gráfica '{ $name }' (sus gráficas: { $known })
detail-no-plot-none = el trabajo '{ $id }' no tiene la gráfica '{ $name }' (no tiene gráficas)
detail-no-file = el trabajo '{ $id }' no tiene el fichero '{ $name }' (sus ficheros: { $known })
detail-no-file-none = el trabajo '{ $id }' no tiene el fichero '{ $name }' (no tiene ninguno)
detail-no-solution = el trabajo '{ $id }' es de tipo { $kind }, que no tiene sólidos libres que resolver (uno de cinetostática sí)
detail-no-template = no hay ninguna plantilla con id '{ $id }' (GET /v1/templates las lista)
text-as-is = { $why }
text-nothing = { "" }
text-value-unit = { $value } { $unit }
detail-in-progress = aún se está respondiendo una petición con Idempotency-Key '{ $key }'; reinténtelo dentro de 1 s
detail-failed = el trabajo '{ $id }' falló y no tiene resultado: GET /v1/jobs/{ $id } dice por qué (su `problem`)
detail-not-done = el trabajo '{ $id }' está { $status }: su resultado aún no está; reinténtelo dentro de 1 s
detail-interrupted = el trabajo se reclamó { $times } veces y cada vez su réplica se detuvo antes de acabar; no se volvió a intentar
detail-no-route = no existe ese recurso
detail-method-not-allowed = método no permitido
detail-result-too-large = el resultado superaría el límite de { $limit } bytes de un resultado
detail-saturated = el servicio está saturado ({ $reason }); reinténtelo dentro de { $seconds } s
saturated-slots = todas las plazas de trabajo y de la cola están ocupadas
saturated-stopping = el servicio se está deteniendo
saturated-queue = los trabajos por delante en la cola no terminaron a tiempo
saturated-memory = se están enviando demasiadas respuestas grandes
saturated-bodies = se están recibiendo demasiados cuerpos de petición
saturated-anonymous = la parte del cálculo para peticiones sin token está ocupada: vuelva a pedirlo en un momento, o inicie sesión
saturated-deferred = hay { $waiting } trabajos diferidos en espera, los más que guarda este servicio
saturated-connections = el servicio tiene abiertas sus conexiones máximas ({ $max }); reinténtelo en un segundo
detail-storage-full = { $what }: el almacenamiento del servicio está lleno; las lecturas siguen funcionando y las escrituras se reanudan cuando vuelve a haber espacio
detail-unavailable = la base de datos no está disponible; reinténtelo más tarde
detail-unauthorized = este servicio guarda y borra trabajos solo para una petición con "Authorization: Bearer <token>": cada POST y DELETE, y un GET del trabajo o la página de una plantilla que guardaría un trabajo nuevo
detail-private-jobs = este servicio reserva sus trabajos guardados a quienes tienen su token: envíe "Authorization: Bearer <token>", o inicie sesión una vez en /signin desde un navegador; los valores de una plantilla (GET /v1/templates/{"{"}id{"}"}/result/…) y sus variantes no necesitan token
detail-length-required = un POST de HTTP/1.0 necesita la cabecera Content-Length: de otro modo no se sabe dónde acaba su cuerpo
detail-internal = error interno; la cabecera x-request-id de esta respuesta lo encuentra en el registro del servicio
detail-job-memory = el trabajo necesitaba más de los { $mib } MiB de memoria que puede usar un trabajo; pida menos pasos, muestras o sólidos
detail-compute-failed = el cálculo del trabajo se detuvo sin respuesta: un fallo del servicio, que la cabecera x-request-id de esta respuesta encuentra en su registro; ningún otro trabajo se vio afectado

## Magnitudes y unidades

unit-malformed = '{ $text }' no es un número seguido de una unidad, p. ej. "300 rpm" o "0,02"
unit-thousands = '{ $text }' lleva separador de miles, que no se lee: escriba { $plain }
unit-unknown = unidad desconocida '{ $unit }'; unidades conocidas: { $known }
unit-unknown-hint = unidad desconocida '{ $unit }'; ¿quería decir { $hint }? Unidades conocidas: { $known }
unit-wrong-dimension = un valor en { $found } donde se espera { $expected }
unit-none = 1 (adimensional)

## Un campo de la petición

field-unknown = campo desconocido
field-unknown-known = campo desconocido (los campos de aquí: { $known })
field-missing = falta un campo obligatorio
field-finite = debe ser finito
field-positive = debe ser mayor que 0
field-too-long = debe tener como mucho { $max } caracteres (tiene { $has })
field-not-angle = '{ $text }' no es ni un ángulo (p. ej. "90 deg" o "90°") ni una expresión constante (p. ej. "7*pi/4")
field-angle-degrees = '{ $text }' no es un ángulo tal como está escrito: los grados se escriben "{ $n }°" o "{ $n } deg"
field-bare-angle = el número sin unidad { $value } se lee en radianes ({ $degrees }°); para grados escriba "{ $value }°"
field-bare-length = el número sin unidad { $value } se lee en metros; para milímetros escriba "{ $value } mm"
field-expression = '{ $text }' es una expresión, no una magnitud: escríbala como {"{"}"expr": "{ $text }"{"}"}
field-expected = se esperaba { $expected } y llegó { $got }
field-between = debe estar entre { $min } y { $max }
field-between-open = debe ser mayor que { $min } y menor que { $max }
field-at-most = debe ser como mucho { $max }
field-at-most-characters = debe tener como mucho { $max } caracteres
field-samples = debe ser 0 (sin tabla) o al menos 2
field-less-than = debe ser menor que { $other }
field-finite-nonzero = debe ser un número finito distinto de cero

## La consulta de una URL

query-unknown = parámetro desconocido (conocidos: { $known })
query-decimal = debe ser point o comma
query-angles = debe ser rad o deg
query-twice = aparece más de una vez: indíquelo una sola vez
query-format = '{ $value }': debe ser csv o json

## Los parámetros de una plantilla

parameter-unknown = la plantilla { $template } no tiene el parámetro { $name } (sus parámetros: { $known })
parameter-not-quantity = '{ $text }' no es ni un número ni una magnitud: { $why }
parameter-finite = debe ser finito
parameter-below = { $text } está por debajo del valor mínimo, { $min }{ $unit }
parameter-above = { $text } está por encima del valor máximo, { $max }{ $unit }
parameter-not-choice = { $text } no es ninguno de { $choices }
parameter-dimension = '{ $text }' está en { $found }, donde se espera { $expected }
parameter-own-unit = la unidad del parámetro { $unit }: { $why }
parameter-nameless = un parámetro sin nombre (`?=...`)

## Tablas CSV

csv-ragged = la fila { $row } tiene { $cells } celdas para { $columns } columnas
csv-ragged-comma = la fila { $row } tiene { $cells } celdas para { $columns } columnas; en un CSV separado por comas, un número con coma decimal se escribe entre comillas ("0,02"), o se separan las columnas con ;
csv-columns = la fila { $row } tiene { $cells } columnas; dé dos: ángulo, valor
csv-columns-comma = la fila { $row } tiene { $cells } columnas; dé dos: ángulo, valor; en un CSV separado por comas, un número con coma decimal se escribe entre comillas ("0,02"), o se separan las columnas con ;

## JSON tal como lo lee una persona

json-number = un número
json-whole = un número entero, 0 o mayor
json-integer = un número entero
json-bool = true o false
json-text = un texto entre comillas
json-array = una lista [...]
json-object = un objeto {"{"}...{"}"}
json-struct = un objeto {"{"}...{"}"} con campos con nombre
json-array-of = una lista de { $n } números
json-tuple = una lista de { $n } elementos
json-got-array = una lista
json-got-object = un objeto
json-got-text = el texto { $text }
json-got-number = el número { $value }
json-got-items = { $n } elemento(s)
json-variant = variante desconocida { $got }, se esperaba { $expected }
json-syntax = { $cause } { $at }{ $hint }
json-at = en la línea { $line }, columna { $column }
json-at-near = en la línea { $line }, columna { $column }, junto a `{ $near }`
json-hint-nan = ; NaN e Infinity no son números de JSON: dé un número finito
json-hint-quotes = ; los textos de JSON van entre comillas dobles
json-hint-comma = ; ¿falta una coma antes?
json-hint-decimal-comma = ; una coma decimal parte un número de JSON: escriba { $dot }, o el texto "{ $comma }"
json-eof-list = la lista termina antes de cerrarse
json-eof-object = el objeto termina antes de cerrarse
json-eof-string = el texto termina antes de cerrarse
json-eof-value = falta un valor al final
json-expected-colon = se esperaba `:`
json-expected-comma-bracket = se esperaba `,` o `]`
json-expected-comma-brace = se esperaba `,` o `{ "}" }`
json-expected-value = se esperaba un valor
json-expected-ident = se esperaba true, false o null
json-invalid-escape = secuencia de escape no válida
json-invalid-number = número no válido
json-number-out-of-range = número fuera de rango
json-key-not-string = la clave debe ser un texto
json-trailing-comma = coma sobrante al final
json-trailing-characters = caracteres sobrantes tras el JSON
json-too-deep = anidamiento demasiado profundo
json-control-character = carácter de control (\u0000-\u001F) dentro de un texto
json-not-utf8 = el cuerpo no está en UTF-8
json-unreadable = no se pudo leer el cuerpo: { $why }
json-variant-one-of = variante desconocida { $got }, se esperaba una de { $expected }
json-variant-either = variante desconocida { $got }, se esperaba { $a } o { $b }
json-expect-quantity = un número (SI) o un texto "VALOR UNIDAD" como "300 rpm"
json-expect-function = un número, un texto con unidad o un objeto con expr, segments o table
json-expect-program = una lista de tramos o un objeto {"{"}"lift": ...{"}"}
json-expect-inputs = un objeto de entrada o una lista de ellos
json-expect-track = el nombre de un punto o un objeto {"{"}"name", "body", "at"{"}"}
json-expect-point = el nombre de un punto o sus coordenadas [x, y] (en el espacio [x, y, z])
json-expect-inertia = un momento de inercia, o en el espacio [Ixx, Iyy, Izz] o una matriz 3×3
json-expect-length = una longitud: un número en m, o con su unidad ("8 cm")
json-expect-fewer = menos elementos (una coma decimal parte en dos un número de JSON: 0,45 se escribe 0.45, o como el texto "0,45")

## Páginas

page-nav-home = Trabajos y plantillas
page-nav-docs = Documentación de la API
page-nav-openapi = Documento OpenAPI
page-footer = mechdyn { $version }: dinámica de máquinas, cada trabajo guardado. Estas páginas no necesitan JavaScript.
page-back = Volver a los trabajos y plantillas
page-home-intro = Dinámica de máquinas: volantes, cinetostática, dinámica directa, rotores, engranajes y levas. Cada trabajo queda guardado; abra uno para ver sus valores, su precisión y sus gráficas, o empiece por el formulario de una plantilla.
page-templates = Plantillas
page-col-template = plantilla
page-col-kind = tipo
page-col-problem = problema
page-recent = Trabajos recientes
page-no-job = Aún no hay trabajos: abra una plantilla o envíe una petición POST:
page-signin-title = Iniciar sesión
page-signin-intro = Los trabajos guardados en este servicio son de quienes tienen su token. Escríbalo una vez: este navegador guarda entonces una cookie que lo representa (30 días, o hasta que cierre la sesión). El formulario de una plantilla, y sus valores por URL, no necesitan token; sin él, un trabajo calculado desde el formulario se muestra pero no se guarda.
page-signin-token = Token
page-signin-button = Entrar
page-signin-wrong = Ese no es el token de este servicio.
page-signed-in = Sesión iniciada.
page-signout-button = Cerrar sesión
page-not-stored = Este trabajo se calculó para esta página y no se guardó: un navegador que no ha iniciado sesión no guarda trabajos en este servicio. Inicie sesión para guardar los trabajos que calcule y volver a leerlos por su dirección.
page-col-job = trabajo
page-col-label = etiqueta
page-col-created = creado (UTC)
page-col-time = tiempo de cálculo, o estado
page-for-programs = Para programas
page-jobs-json = trabajos (JSON)
page-templates-json = plantillas (JSON)
page-job-title = trabajo { $kind }
page-job-title-label = trabajo { $kind }: { $label }
page-job = trabajo
page-created = creado
page-label = etiqueta
page-engine = motor de cálculo
page-csv-table = tabla CSV
page-every-value = todos los valores (CSV)
page-plots-json = gráficas (JSON)
page-values = Valores
page-long-tables = Tablas del resultado (sus filas están en el CSV):
page-rows = { $n } filas
page-request = Petición
page-request-sent = La petición tal como se envió
page-failed = Falló: { $title }
page-waiting = Este trabajo está { $status }; esta página mostrará su resultado cuando termine.
page-accuracy = Precisión y tiempo
page-accuracy-check-relative-difference = comprobación con otro método (diferencia relativa)
page-accuracy-constraint-drift = deriva de las restricciones
page-accuracy-energy-form-time-difference = forma de energía frente a forma temporal (diferencia)
page-accuracy-energy-residual = residuo de energía
page-accuracy-estimated-error = error estimado
page-accuracy-estimated-relative-error = error relativo estimado
page-accuracy-function-evaluations = evaluaciones de la función
page-accuracy-integrator = integrador
page-accuracy-max-constraint-residual = mayor residuo de las restricciones
page-accuracy-max-friction-iterations = máximo de iteraciones de rozamiento
page-accuracy-max-newton-iterations = máximo de iteraciones de Newton
page-accuracy-method = método
page-accuracy-quadrature-error = error de cuadratura
page-accuracy-steps = pasos
page-accuracy-virtual-power-residual = residuo de potencia virtual
page-computed-in = Calculado en { $time } de tiempo de cálculo.
page-no-accuracy = Este tipo de cálculo no da una estimación propia de su precisión.
page-warnings = Avisos
page-plots = Gráficas
page-draw-at = Dibujar el mecanismo en el paso
page-draw = Dibujar
page-more-plots = Más gráficas de este trabajo:
page-col-quantity = magnitud (puntero JSON)
page-col-value = valor
page-col-unit = unidad
page-full-value = el valor completo
page-template-meta = plantilla { $id } · un trabajo { $kind }
page-form-help = Un número se lee en la unidad que figura junto a su nombre (con coma decimal si se quiere: 0,03); una magnitud con su propia unidad ("300 rpm", "4 %", "20°") se lee en esa unidad; un campo en blanco conserva su valor por defecto.
page-compute = Calcular
page-form-url = El mismo trabajo por URL, para una hoja de cálculo o un programa:
page-form-url-json = (JSON), o un solo número:
page-name-value = NOMBRE=VALOR
page-pointer = PUNTERO
page-one-of = uno de { $choices }
page-from-to = de { $min } a { $max }{ $unit }
page-at-least = al menos { $min }{ $unit }
page-at-most = como mucho { $max }{ $unit }

## Gráficas

plot-phi-shaft = ángulo del eje de reducción φ
plot-torque-shaft = par en el eje de reducción
plot-work-since = trabajo desde φ = 0, W(φ)
plot-speed-shaft = velocidad del eje de reducción ω
plot-reduced-inertia = inercia reducida I*(φ)
plot-flywheel-torque = Par reducido M*(φ) y los lóbulos de trabajo A_i
plot-flywheel-work = Trabajo W(φ) a lo largo del ciclo y fluctuación de energía ΔE
plot-flywheel-speed = Velocidad ω(φ) a lo largo del ciclo con la inercia exacta del volante
plot-flywheel-wittenbauer = Diagrama de Wittenbauer: W frente a I*(φ) y las tangentes que dan la inercia del volante
plot-flywheel-other-torques = M_b − M*: los demás pares, cambiados de signo
plot-flywheel-balance = par motor de equilibrio M_b = { $value } N·m
plot-flywheel-lobes =
    { $n ->
        [one] 1 lóbulo; en verde donde los pares aportan trabajo (A_i > 0), en rojo donde lo consumen
       *[other] { $n } lóbulos; en verde donde los pares aportan trabajo (A_i > 0), en rojo donde lo consumen
    }
plot-flywheel-speed-note = grado de irregularidad ε = (ω_max − ω_min)/ω_a = { $eps }; I = { $inertia } kg·m² (exacta)
plot-wittenbauer-curve = W frente a I* a lo largo del ciclo
plot-tangent-max = tangente de pendiente ω_max²/2, ω_max = { $value } rad/s
plot-tangent-min = tangente de pendiente ω_min²/2, ω_min = { $value } rad/s
plot-wittenbauer-note = Las tangentes se cortan en (−I, −T₀) = ({ $x } kg·m², { $y } J), fuera de esta vista: I = { $inertia } kg·m² (exacta), T₀ = { $t0 } J
plot-joint = par { $joint }
plot-most-joints = los { $most } mayores de { $total } pares; la gráfica propia de cada par muestra el resto
plot-reactions-to-scale = reacciones en los pares a escala: la mayor, { $force } N, dibujada de { $length } m
plot-free-body = Sólido libre de { $body } ({ $number }), paso { $step }
plot-free-body-sums = ΣFx = { $fx } N, ΣFy = { $fy } N, ΣM_G = { $moment } N·m
plot-free-body-sums-spatial = vista isométrica, { $up } arriba; ΣF = ({ $forces }) N, ΣM_G = ({ $moments }) N·m
plot-moments-to-scale = pares como vectores momento (doble punta): el mayor, { $moment } N·m, dibujado de { $length } m
plot-forces-to-scale = fuerzas a escala: la mayor, { $force } N, dibujada de { $length } m
plot-ks-driving = Acción motriz frente a la entrada
plot-ks-reactions = Reacciones en los pares |R| frente a la entrada
plot-ks-polar = Diagrama polar de la reacción en el par { $joint }
plot-ks-reduced-inertia = Inercia reducida I*(φ)
plot-ks-reduced-torque = Par reducido M*(φ) de las cargas
plot-ks-mechanism = El mecanismo en un paso, con las reacciones en sus pares a escala
plot-ks-reduced-torque-line = M*(φ), las cargas reducidas a la entrada
plot-ks-input-angle = ángulo de entrada en el par { $joint }
plot-ks-input = entrada en el par { $joint }
plot-ks-driving-force = fuerza motriz
plot-ks-driving-torque = par motor
plot-ks-at-joint = en el par { $joint }
plot-ks-mean = media { $value }
plot-ks-reaction-force = fuerza de reacción |R|
plot-ks-force-on-by = fuerza sobre { $on } ejercida por { $by } a lo largo del barrido
plot-ks-origin = origen (0, 0)
plot-ks-first-step = primer paso
plot-ks-first-step-at = primer paso (entrada { $value })
plot-ks-polar-note = la fuerza es el vector del origen a la curva; la mayor { $value } N
plot-ks-step = paso { $step } de 0 a { $last }: entrada { $value }
plot-flywheel-motion = La máquina en movimiento durante un ciclo, a la velocidad del volante
plot-flywheel-motion-at = φ = { $phi }° · ω = { $omega } rad/s
plot-cursor = paso { $step }
plot-ks-motion = El mecanismo en movimiento a lo largo del barrido
plot-ks-motion-at = entrada { $value } · paso { $step }
plot-dyn-motion = El mecanismo en movimiento a lo largo de la simulación
plot-dyn-motion-at = t = { $t } s · muestra { $step }
plot-motion-note-paths = un ciclo en { $seconds } s; a trazos: las trayectorias
plot-motion-note = un ciclo en { $seconds } s; a trazos: las trayectorias; reacciones a una misma escala
plot-ks-shaking = Fuerza de sacudimiento sobre el bastidor (diagrama polar)
plot-ks-shaking-moment = Momento de sacudimiento sobre el bastidor frente a la entrada
plot-ks-shaking-moment-axis = momento de sacudimiento respecto al origen
plot-ks-shaking-force = −Σ m·a_G a lo largo del barrido
plot-ks-shaking-balanced = con los contrapesos
plot-time = tiempo t
plot-angle = ángulo φ
plot-speed = velocidad ω
plot-dyn-angle = Ángulo frente al tiempo, con los sucesos
plot-dyn-speed = Velocidad frente al tiempo, con los sucesos
plot-dyn-phase = Retrato de fase: velocidad frente a ángulo
plot-dyn-energy = Residuo de energía frente al tiempo
plot-dyn-reactions = Reacciones en los pares |R| frente al tiempo
plot-dyn-mechanism = El mecanismo en una muestra, sobre las trayectorias de sus pares
plot-dyn-mechanism-spatial = El mecanismo en una muestra, con las reacciones en sus pares a escala
plot-dyn-path = Trayectoria del par { $joint }
plot-dyn-phase-line = ω frente a φ
plot-dyn-residual = residuo de energía (W − ΔT)/max(|W|, |ΔT|, T₀, T, T_pico)
plot-dyn-residual-line = potencia integrada W frente a la energía cinética T
plot-dyn-residual-note = al final { $value }: cuánto deriva el balance de energía de la integración
plot-dyn-input-at = { $symbol }(t) en el par { $joint }
plot-dyn-turn = vuelta { $n }
plot-dyn-slip = desliza { $joint }
plot-dyn-roll = rueda { $joint }
plot-dyn-end = fin
plot-dyn-note =
    { $turns ->
        [one] 1 vuelta
       *[other] { $turns } vueltas
    }; residuo de energía { $residual }; error estimado del ángulo { $error } rad
plot-dyn-note-few =
    { $turns ->
        [one] 1 vuelta
       *[other] { $turns } vueltas
    }; residuo de energía { $residual }; error estimado del ángulo { $error } rad; solo { $samples } muestras, unidas por rectas (pida más: samples)
plot-dyn-at-start = { $joint } en t = 0
plot-dyn-at-end = { $joint } al final
plot-dyn-path-line = trayectoria del par { $joint }
plot-dyn-sample = muestra { $step } de 0 a { $last }: t = { $t } s; a trazos: las trayectorias de los pares
plot-dyn-sample-spatial = muestra { $step } de 0 a { $last }: t = { $t } s
plot-isometric = vista isométrica, { $up } arriba; a trazos: los ejes de los pares; flechas: las reacciones a escala
plot-cam-svaj = Elevación, velocidad, aceleración y sobreaceleración frente al ángulo de leva (cada una sobre su máximo)
plot-cam-profile = El perfil de la leva, la curva primitiva y la circunferencia base, el seguidor en el mayor ángulo de presión
plot-cam-pressure = Ángulo de presión y radio de curvatura frente al ángulo de leva
plot-cam-forces = Fuerza de contacto y par en la leva frente al ángulo de leva
plot-cam-angle = ángulo de leva θ
plot-cam-pressure-title = Ángulo de presión y radio de curvatura
plot-cam-pressure-line = ángulo de presión φ (°)
plot-cam-curvature-line = radio de curvatura del perfil ρ (mm)
plot-cam-forces-title = Fuerza de contacto y par en la leva
plot-cam-contact-force = fuerza de contacto (N)
plot-cam-torque = par en la leva (N·m)
plot-cam-svaj-title = Diagrama SVAJ
plot-cam-over-peak = cada una sobre su máximo
plot-cam-law-ends = fin de { $law }
cam-law-dwell = reposo
cam-law-harmonic = armónica
cam-law-cycloidal = cicloidal
cam-law-polynomial-345 = polinómica 3-4-5
cam-law-polynomial-4567 = polinómica 4-5-6-7
cam-law-modified-sine = seno modificado
cam-law-modified-trapezoid = trapecio modificado
plot-cam-profile-title = Perfil de la leva (ejes de la leva, x: la dirección del seguidor en θ = 0)
plot-cam-profile-title-pivot = Perfil de la leva (ejes de la leva, x: hacia el pivote del seguidor)
plot-cam-profile-line = perfil
plot-cam-base = circunferencia base R_b = { $value } mm
plot-cam-pitch = curva primitiva
plot-cam-follower-worst = seguidor en el mayor ángulo de presión
plot-cam-worst-at = φ = { $phi }° en θ = { $theta }°
plot-rotor-bearings = Reacciones en los cojinetes a lo largo de los estados, en ejes fijos
plot-rotor-frame-angle = ángulo del bastidor
plot-rotor-force = fuerza sobre el sólido
plot-rotor-bearing = cojinete { $name }
plot-rotor-note = reacción total (estática y dinámica) de cada cojinete; se omiten las componentes que siguen siendo cero
plot-balancing-vectors = Desequilibrio y correcciones (m·r, vistos a lo largo del eje)
plot-balancing-unbalance = desequilibrio estático U
plot-balancing-correction = corrección en z = { $z } m
plot-balancing-note = vectores m·r desde el eje, a una misma escala; cada corrección en su plano
plot-gear-tooth = Los dientes de evolvente, a partir de la geometría calculada
plot-gear-profile = perfil del diente
plot-gear-pitch = circunferencia primitiva r = { $value } mm
plot-gear-base = circunferencia base r_b = { $value } mm
plot-gear-tip = cabeza r_a = { $tip } mm, pie r_f = { $root } mm
plot-gear-thickness = s = { $value } mm en la circunferencia primitiva
plot-gear-note = z = { $z }, ángulo de presión { $alpha }° en la circunferencia primitiva; bajo la circunferencia base el flanco se dibuja radial
plot-gear-note-pointed = z = { $z }, ángulo de presión { $alpha }° en la circunferencia primitiva; bajo la circunferencia base el flanco se dibuja radial; los flancos se cortan antes de la circunferencia de cabeza (diente en punta)

## Los tipos de trabajo, nombrados para las personas

kind-flywheel = volante
kind-kinetostatics = cinetostática
kind-dynamics = dinámica directa
kind-cams = diseño de levas
kind-rotor = rotor
kind-balancing = equilibrado
kind-gears = engranajes
kind-gear-train = tren de engranajes
kind-equivalent = masas equivalentes
kind-mobility = movilidad
kind-check = comprobación

## La petición de un volante

flywheel-speeds = dé exactamente una de estas parejas: mean_speed + irregularity, mean_speed + min_speed, min_speed + max_speed
flywheel-torques-count = debe tener de 1 a { $max } elementos (o dé una máquina)
flywheel-one-balance = como mucho un elemento puede tener "balance": true
flywheel-value-or-balance = dé "value" o bien "balance": true
flywheel-disk-density = un disco dimensionado por su espesor necesita su densidad
flywheel-disk = dé exactamente uno de rim_speed, radius o thickness

## La petición de una corrección, el CSV de una clase, un estudio

field-finite-not-negative = debe ser un número finito ≥ 0
field-whole-not-negative = debe ser un número entero ≥ 0
query-true-false = debe ser true o false
query-values-none = indique los valores que responder, p. ej. ?values=inertia_exact,energy_fluctuation
csv-not-utf8 = el CSV no es texto UTF-8
csv-header = la cabecera del CSV: { $why }
csv-unreadable = el CSV: { $why }
csv-too-many-rows = más de { $max } filas en una petición
template-not-drawable = la plantilla { $id } no tiene ningún parámetro con opciones ni con min, max y step: todas las variantes serían sus valores por defecto
template-seed-range = las variantes se numeran de 0 a 2^63 − 1: seed + count − 1 no debe pasar de ahí
check-reference-none = indique la referencia: template (con parameters o variant), kind con request, o job
check-reference-more = indique una sola referencia: template, kind con request, o job
check-kind-alone = kind necesita la petición (request)
check-request-alone = request necesita su tipo (kind)
check-parameters-alone = parameters es de una plantilla (template)
check-variant-alone = una variante es de una plantilla (template)
check-variant-range = las variantes se numeran de 0 a 2^63 − 1
check-parameters-and-variant = dé parameters o una variante, no ambos
check-answers-none = al menos una respuesta: {"{"}"PUNTERO": valor{"}"}
check-answers-too-many = como mucho { $max } respuestas (tiene { $count })
check-answered-twice = { $pointer } se responde dos veces
check-required-too-many = como mucho { $max } punteros
check-tolerance-unanswered = ninguna respuesta tiene este puntero
check-sigfigs = debe ser de 1 a 15
check-kind-unknown = '{ $name }' no es un tipo de trabajo con el que corregir (uno de { $known })
check-template-unknown = no hay ninguna plantilla '{ $id }' (GET /v1/templates las lista)
check-job-offline = un trabajo guardado necesita el almacén del servicio
class-student-column = el CSV necesita una columna `student`
class-answers-none = no hay columnas de respuestas: nombre cada una por su puntero en el resultado, p. ej. inertia_exact
class-reserved = un nombre reservado, no un puntero en el resultado
class-variant-and-parameters = dé una variante o los parámetros del alumno, no ambos
class-variant-none = ni variante (ni parámetros) para este alumno
class-variant-number = '{ $text }' no es un número de variante (de 0 a 2^63 − 1)
class-row-no-student = la fila { $row } no tiene alumno
class-student-twice = el alumno { $student } aparece dos veces
check-no-value = el resultado de { $kind } no tiene ningún valor en { $pointer }
check-not-graded = { $pointer } no es un número ({ $value }): solo se corrigen números

## Una plantilla tal como la escribe un cliente

template-kind-unknown = tipo desconocido '{ $kind }' (conocidos: { $known })
template-request-object = debe ser un objeto de petición de ese tipo
template-name-slug = '{ $name }' no es un identificador: letras minúsculas, dígitos y -, como mucho 64
template-parameters-too-many = como mucho { $max } parámetros
template-no-parameter = no hay ningún parámetro { $name } en esta plantilla
template-parameter-name = '{ $name }' no es un nombre: letras, dígitos y _, sin empezar por un dígito
template-parameter-reserved = '{ $name }' está reservado en la URL de una plantilla ({ $reserved })
template-pointer-scalar = debe apuntar a un número o a un texto de la petición
template-pointer-missing = { $pointer } no está en la petición
template-min-above-max = min { $min } está por encima de max { $max }
template-no-statement = la plantilla no tiene la magnitud del enunciado { $name }
template-statement-too-many = como mucho { $max } magnitudes del enunciado
template-statement-pointer = "of" es un puntero JSON al resultado, como "/balance_torque"
template-statement-sign = "sign" es 1 o -1
template-derived-too-many = como mucho { $max } valores derivados
template-derived-expression = la expresión del valor derivado no se entiende: { $why }
template-derived-finite = el valor derivado sale { $value }, no un número finito

## Cabeceras, etiquetas, listas

field-one-of = debe ser uno de { $known }
field-integer-between = debe ser un entero de { $min } a { $max }
header-ascii = debe ser ASCII visible
header-characters = debe tener de 1 a { $max } caracteres
header-key-reused = esta clave se envió antes con otra petición (método, ruta, consulta o cuerpo); use una clave nueva para una petición nueva
label-control = no debe contener caracteres de control ni de cambio de dirección (contiene { $code })
label-empty = no debe estar vacía

## Una parte de un resultado en otra unidad

unit-part-not-number = la parte en { $pointer } no es un número: no tiene unidad que convertir
unit-part-no-unit = la parte en { $pointer } no tiene unidad que convertir
unit-part-no-single-unit = la parte en { $pointer } está en { $unit }, que no es una sola unidad desde la que convertir
unit-target = '{ $target }': { $why }
unit-part-in = '{ $target }' es una unidad de { $found }; la parte en { $pointer } está en { $unit }
unit-part-in-of = '{ $target }' es una unidad de { $found }; la parte en { $pointer } está en { $unit }, una unidad de { $expected }
query-whole-number = '{ $text }': debe ser un número entero desde 0
query-step = '{ $text }': debe ser un número entero de 0 a { $last }
parameter-pointer-missing = apunta a { $pointer }, que no está en la petición

## Un resultado demasiado grande

size-would-be = el resultado ocuparía { $size } ({ $bytes } bytes), más del límite de { $limit } de un resultado (MECHDYN_MAX_RESULT_BYTES)
size-would-be-about = el resultado ocuparía unos { $size } ({ $bytes } bytes), más del límite de { $limit } de un resultado (MECHDYN_MAX_RESULT_BYTES)
size-would-be-at-least = el resultado ocuparía al menos { $size } ({ $bytes } bytes), más del límite de { $limit } de un resultado (MECHDYN_MAX_RESULT_BYTES)
size-too-large = { $size }; { $advice }
size-advice = a { $each } cada una, con { $name } ≤ { $fit } cabría{ $also }
size-advice-at-most = a { $each } o más cada una, no cabrían más de { $fit } { $name }{ $also }
size-also-events = { " " }(eventos: uno por vuelta, menos con una integración más corta)
size-also-table = { " " }(0 para no dar tabla)
size-also-outputs = ; o pida menos "outputs" (la cinemática de cada sólido es la mayor)

## El paso de un dibujo

plot-no-steps = { $step }: este trabajo no dibuja ningún mecanismo, así que no tiene pasos que elegir
plot-singular-step = { $step }: en este paso el mecanismo está en una posición singular, donde no se resuelve ninguna fuerza; elija un paso próximo
plot-steps = { $step }: el trabajo tiene { $count ->
        [one] 1 paso (0)
       *[other] { $count } pasos (de 0 a { $last })
    }

## Conflictos, presupuestos, cuerpos lentos

template-builtin = '{ $id }' es una plantilla incorporada
template-exists = ya existe una plantilla llamada '{ $id }'
detail-over-budget = se agotó el presupuesto de cálculo de { $seconds } s ({ $progress }); pida menos pasos, muestras o sólidos, o una tolerancia más holgada
progress-flywheel-sampling = detenido al muestrear M* e I*
progress-flywheel-work = detenido al integrar el trabajo de cada par
progress-flywheel-crossings = detenido al localizar los cruces y lóbulos de M*
progress-flywheel-exact = detenido al hallar la inercia exacta
progress-flywheel-time-check = detenido al comprobar por integración en el tiempo
progress-flywheel-table = detenido al muestrear la tabla
progress-late = la solución estaba completa, pero fuera de plazo
progress-assembling-machine = al montar la máquina
progress-assembled = el mecanismo se había montado en { $step } de { $of } posiciones
progress-candidates = se habían buscado las entradas hasta el par { $joint } de { $of }
progress-cam-size = se habían probado { $tried } radios base en la búsqueda del menor
rows-budget-spent = sin calcular: el presupuesto de cálculo de esta petición, { $seconds } s, se agotó en las filas anteriores; vuelva a pedirla para el resto (las filas hechas están guardadas y se encuentran al instante) o envíe menos filas
progress-friction = se iteraba el rozamiento de los pares en la posición { $step }
progress-approach = el mecanismo había recorrido { $step } de { $of } pasos desde su dibujo hacia la primera posición
progress-cam-lift = se había evaluado la alzada en { $angle } de { $of } ángulos
progress-reading = mientras se leía la petición: al montar su croquis, situar sus contactos o preparar sus entradas
progress-stopped = no se detuvo por sí mismo, y se detuvo desde fuera
detail-request-timeout = el cuerpo de la petición no llegó a tiempo: { $read } bytes en { $seconds } s; este servicio necesita que el cuerpo siga llegando a { $rate } bytes/s pasados { $grace } s

## La solución desarrollada (sólidos libres)

page-solution-title = Solución desarrollada, paso { $step }
page-solution-input = Entrada:
page-solution-job = El trabajo
page-solution-previous = Paso anterior
page-solution-next = Paso siguiente
page-solution-numbering = Los sólidos, numerados
page-solution-order = El orden de la solución
page-solution-order-why = Las ecuaciones de cada grupo dan sus incógnitas una vez resueltos los grupos anteriores: desde el último grupo del mecanismo hasta su entrada.
page-solution-group = { $bodies }: sus ecuaciones dan { $unknowns }
page-solution-diagram = Diagrama de sólido libre de { $body }, sus fuerzas a una misma escala
page-solution-action = Acción
page-solution-from = Ejercida por
page-solution-at = Punto (m)
page-solution-reaction = reacción
page-solution-inertia = inercia
page-solution-weight = peso
page-solution-driving = motriz
page-solution-load = carga
page-solution-power = Potencias virtuales
page-solution-power-why = La potencia de cada acción en este paso: por el principio de las potencias virtuales suman cero (las dos caras de un par se anulan salvo su rozamiento).
page-solution-reactions = reacciones (su rozamiento)
page-solution-total = total
page-solution-link = Solución desarrollada (sólidos libres)
page-solution-at-step = Resolver el paso
page-solution-solve = Resolver
