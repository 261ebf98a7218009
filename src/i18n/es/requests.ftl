# Las peticiones de cada tipo: lo que debe ser un campo de un mecanismo,
# una leva, un rotor, un tren de engranajes…, en español (inglés en
# ../en/requests.ftl, con los mismos identificadores y argumentos).

## Un mecanismo: sus puntos, cuerpos, la gravedad y los errores de su montaje

mechanism-too-many = como mucho { $max } cuerpos y { $max } pares cinemáticos
mechanism-coordinates = las coordenadas deben ser finitas
mechanism-unknown-point = punto desconocido '{ $name }'
mechanism-unknown-body = cuerpo desconocido '{ $name }' (los cuerpos: { $known })
mechanism-unknown-joint = par cinemático desconocido '{ $name }'
mechanism-duplicate-body = nombre de cuerpo repetido '{ $name }' (ground, el bastidor, ya existe sin declararlo)
mechanism-duplicate-joint = nombre de par cinemático repetido '{ $name }'
mechanism-cg = un cuerpo con masa necesita "cg", su centro de masas
mechanism-not-negative = no debe ser negativo
mechanism-gravity = debe ser [gx, gy], con valores finitos
mechanism-vector = debe ser un vector [x, y] finito y no nulo
mechanism-vector-in-space = tres componentes, un vector en el espacio: un mecanismo espacial dice "space": "spatial"; en el plano [x, y]
mechanism-not-finite = { $function } no es finita en phi = { $phi } rad
mechanism-negative-inertia = { $function } es negativo ({ $value } kg*m^2) en phi = { $phi } rad
mechanism-not-steady = el ciclo no es estacionario: el trabajo neto de los pares en un ciclo es { $net_work } J (lóbulo mayor { $largest_area } J); añada un par con "balance": true o corrija las cargas
mechanism-newton = el mecanismo no se puede montar en la entrada { $input } (paso { $step }): el lazo que pasa por { $joint } no cierra (Newton-Raphson se detuvo a { $residual } de cerrarlo; p. ej. una manivela que no cumple Grashof a la que se pide una vuelta completa)
mechanism-locked = el mecanismo está bloqueado: sus pares cinemáticos no le dejan ningún grado de libertad (0 por el rango del jacobiano de los pares; el recuento de Grübler 3(N - 1) - 2 P_I - P_II = { $grubler }), así que ninguna entrada puede moverlo; quite un par cinemático o convierta uno en deslizadera
mechanism-singular = el mecanismo está en una posición singular en el paso { $step } (entrada { $input }): el jacobiano de las restricciones pierde rango
mechanism-singular-cycle = la máquina no puede pasar { $count } { $count ->
    [one] posición
   *[other] posiciones
    } de su ciclo, la primera en la entrada { $input }: el mecanismo es singular ahí, o un punto se va al infinito (una ranura en el cuerpo equivocado da y = d·tg φ), así que su inercia reducida I* y su par reducido M* no son finitos en el ciclo y no puede dimensionarse un volante para ella
mechanism-dof =
    el mecanismo tiene { $dof ->
        [one] 1 grado de libertad
       *[other] { $dof } grados de libertad
    } pero { $inputs ->
        [one] 1 entrada
       *[other] { $inputs } entradas
    }: dé una entrada por grado de libertad (un cuerpo con pocos pares cinemáticos se mueve libremente; demasiadas entradas entran en conflicto)
mechanism-friction = ningún esfuerzo finito acciona el mecanismo en la entrada { $input } (paso { $step }) con este rozamiento (autobloqueo): solo se movería con coeficientes de rozamiento por debajo del { $percent } % de los dados
mechanism-unactuated = los actuadores { $actuators } no pueden accionar las entradas en la entrada { $input } (paso { $step }): mover las entradas no los mueve (su esfuerzo lo soportarían los pares cinemáticos); elija un actuador que el movimiento de la entrada mueva
mechanism-not-finite-result = el cálculo produjo un número no finito; los datos son numéricamente degenerados

## Los pares cinemáticos de un mecanismo

joint-two-bodies = debe nombrar exactamente dos cuerpos
joint-same-body = un par cinemático no puede unir un cuerpo consigo mismo
joint-at = "at" es obligatorio
joint-axis = "axis" es obligatorio para este tipo de par cinemático
joint-gear-ratio = un engranaje necesita una relación de transmisión "ratio" finita y no nula, o "teeth": [z1, z2] (números de dientes positivos)
joint-gear-teeth = un engranaje con módulo necesita "teeth": [z1, z2], sus números de dientes
joint-gear-bearings = un engranaje con módulo necesita un par de rotación (su cojinete) en cada rueda, para hallar su centro
joint-gear-friction = el rozamiento no se modela en los engranajes
joint-length-prismatic = solo se aplica a los pares prismáticos (la longitud de una guía)
joint-length-one = dé "length" (la de la guía, en el primer sólido) o "slider_length" (la del bloque, en el segundo), no ambas
joint-mu = debe ser un número finito ≥ 0
joint-friction-radius = el rozamiento de un par de rotación necesita el radio "radius" del pasador
joint-radius-revolute = solo se aplica a los pares de rotación
joint-contact-only = solo se aplica a los pares de contacto

## Un par de contacto: sus curvas y dónde se tocan

contact-needs-curves = un par de contacto necesita "curves": una curva por cuerpo
contact-two-curves = debe tener exactamente dos curvas, la del primer cuerpo y la del segundo
contact-point-rolling = un punto no puede rodar: la rodadura necesita dos curvas
contact-gap = las curvas no se tocan tal como están dibujadas: están a { $gap } m cerca de ({ $x }; { $y }) (deben encontrarse a menos de { $tolerance } m, 1e-6 del tamaño del mecanismo)
contact-cross = las curvas se cortan en ({ $x }; { $y }) con un ángulo de { $angle }° en lugar de tocarse (con una tangente común): dibújelas en contacto
contact-lines = dos rectas no forman un contacto (se tocan a lo largo de toda su longitud o se cortan): use un par prismático
contact-spline-points = debe tener de 4 a { $max } puntos
contact-no-spline = ningún spline pasa por estos puntos
contact-circle-fills = un círculo de radio { $radius } m dentro de otro del mismo radio lo toca en toda la vuelta: no puede rodar ni deslizar en él (haga menor el interior)
contact-spline-repeated = repite el punto { $other }: un spline que pasa dos veces por un punto dibuja un bucle que nadie dibujó; dé cada punto una vez (un spline cerrado une su último punto con el primero por sí solo)
contact-polar-positive = debe ser positivo en toda la vuelta: r({ $angle }°) = { $value }
contact-cam-ccw = el programa de una curva de leva va en sentido antihorario: escríbalo en el ángulo antihorario (ccw) de la leva
contact-cam-segments = una curva de leva toma un programa de tramos
contact-cam-offset = debe ser menor que el radio de la circunferencia primitiva (círculo base + rodillo)
contact-cam-oscillating = una curva de leva se construye para un seguidor de traslación: para uno oscilante, dibuje el perfil que da su diseño (POST /v1/cams: el profile_point de las muestras) como un spline cerrado

## Las cotas de un mecanismo

dimensions-too-many = como mucho { $max } cotas
dimensions-one-of = dé exactamente una de "distance", "angle", "x", "y" y "on"
dimensions-between = dé los dos puntos "between" [A, B] entre los que está el punto "on"
dimensions-ratio = dé "ratio", la fracción de A→B a la que está el punto (0,5: el punto medio)
dimensions-value = dé el valor de la cota, "value" (una longitud, o un ángulo para "angle")
dimensions-two-points = debe nombrar dos puntos
dimensions-unknown-point = punto desconocido '{ $name }' (las cotas unen puntos con nombre)
dimensions-positive = debe ser positiva
dimensions-conflict = no se pueden cumplir todas las cotas: esta y las que se nombran con ella (difieren en { $residual } con el menor cambio)
dimensions-reversed = el croquis dibuja esta recta en sentido contrario: intercambie sus puntos, o sume 180° al ángulo

## Las cargas de un mecanismo

load-too-many = como mucho { $max } cargas
load-needs = una carga de tipo { $type } necesita "{ $field }"
load-not-this-type = no se aplica a este tipo de carga
load-ground = una carga sobre el bastidor no hace nada; nombre un cuerpo móvil

## Los puntos que sigue una petición

track-too-many = como mucho { $max } puntos
track-pin = '{ $point }' es el pasador de la ranura '{ $slot }': sus dos cuerpos se mueven de forma distinta allí; dé {"{"}"name": "{ $point }", "body": ...{"}"}
track-no-body = '{ $point }' no está en ningún cuerpo (allí no hay ningún par cinemático ni centro de masas); dé {"{"}"name": "{ $point }", "body": ...{"}"}

## Las entradas de un mecanismo

input-ground = el bastidor (ground) no se mueve: nombre un cuerpo móvil
input-joint-kind = una entrada debe ser un par de rotación, prismático o de contacto (la longitud de arco a lo largo de su curva)
input-on-ground = '{ $point }' está en el bastidor: no se mueve
input-direction-of-point = pertenece a una entrada "point"
input-none = nombre el par cinemático "joint" de la entrada, o un punto "point" y su dirección "direction", o un cuerpo "body"
input-one-of = nombre solo uno de "joint", "point" (con "direction") o "body"
input-needs-direction = una entrada "point" necesita su dirección "direction" [x, y]
input-direction = debe ser un [x, y] finito y no nulo
input-flywheel-shaft = la entrada de un volante es su eje: un par de rotación "joint"
input-shaft-revolute = el eje del volante debe ser un par de rotación
input-shaft-rotation = el eje del volante gira: nombre un par de rotación, o uno cilíndrico con "coordinate": "rotation"
input-name-shaft = nombre el eje, un par de rotación
input-count = dé de 1 a 10 entradas
input-steps = debe ser de 1 a { $max }
input-same-steps = todas las entradas comparten los pasos "steps" de la primera
input-actuators =
    dé un actuador por entrada: { $inputs ->
        [one] 1 entrada
       *[other] { $inputs } entradas
    }, { $actuators ->
        [one] 1 actuador
       *[other] { $actuators } actuadores
    }
input-own-actuator = cada entrada necesita su propio actuador: '{ $name }' ya acciona otra
input-actuator-kind = un actuador debe ser un par de rotación (da un par) o uno prismático (da una fuerza)
input-needs-end = una entrada en metros (un par prismático, un punto sobre una guía, la longitud de arco de un contacto) necesita "end" (o "steps": 1, una sola posición)
input-speed = "speed" es obligatorio

## Cinetostática: lo que pide de sus resultados, y las posiciones que un mecanismo no alcanza

kinetostatics-points-track = "points" sigue los puntos de "track": indíquelos
balance-fraction = la fracción alternativa está entre 0 y 1, no { $value }
balance-unknown-body = ningún cuerpo se llama «{ $body }»
balance-not-linkage = los contrapesos se calculan para un cuadrilátero articulado (manivela, biela, balancín) o un biela-manivela (manivela, biela, corredera), con pares de rotación y la corredera unida al bastidor por un par prismático: este mecanismo no es ninguno de los dos
balance-not-pivoted = «{ $body }» no está articulado al bastidor: los contrapesos van en la manivela y, en un cuadrilátero, en el balancín
balance-missing = el equilibrado completo de fuerzas de un cuadrilátero necesita también un contrapeso en «{ $body }»
balance-missing-crank = el contrapeso de un biela-manivela va en su manivela, «{ $body }»
balance-twice = «{ $body }» está dos veces
kinetostatics-at = { $what } en la entrada { $value } (paso { $step } de { $steps }): { $why }
kinetostatics-at-start = { $what } en la entrada { $value } (paso { $step } de { $steps }, el inicio): { $why }
kinetostatics-on-the-way = { $said }; en el camino hasta allí desde la configuración dibujada (la "reference" de la entrada) deja de cerrar en { $value }
kinetostatics-value-rad = { $value } rad = { $degrees } deg
kinetostatics-not-assembled = el mecanismo no se puede montar
kinetostatics-loop = el lazo que pasa por { $joint } no cierra (Newton-Raphson se queda a { $residual } de cerrarlo); revise start, end y las longitudes ({ $why })
kinetostatics-loop-crank = una manivela que no cumple Grashof, por ejemplo, no puede dar una vuelta completa
kinetostatics-loop-slider = una deslizadera llevada hasta un punto muerto o más allá, por ejemplo, donde la posición del mecanismo no es función de la suya: empiece y acabe antes, o accione la manivela; o un seguidor más allá de donde su curva lo sostiene
kinetostatics-singular = el mecanismo está en una posición singular
kinetostatics-dead-centre = un punto muerto que la entrada no puede pasar (el jacobiano de las restricciones pierde rango)
kinetostatics-friction = el rozamiento en los pares cinemáticos bloquea el mecanismo
kinetostatics-self-locking = ningún esfuerzo finito lo acciona ahí con este rozamiento (autobloqueo): solo se movería con coeficientes de rozamiento por debajo del { $percent } % de los dados
kinetostatics-unactuated = los actuadores no pueden accionar las entradas
kinetostatics-unactuated-why = mover las entradas no mueve { $actuators } ahí, así que su esfuerzo lo soportarían los pares cinemáticos; nombre en "actuators" un par cinemático que el movimiento de la entrada mueva

## Dinámica directa: sus dos formas, cómo acaba una simulación, y una simulación que no se puede hacer

dynamics-machine-or-reduced = dé "machine" o bien la forma reducida, no ambas
dynamics-reduced-or-machine = dé la forma reducida ("torques" con "reduced_inertia") o bien "machine", no ambas
dynamics-machine-required = obligatorio: dé "machine" (un mecanismo y sus cargas) o la forma reducida "torques" con "reduced_inertia"
dynamics-samples = debe ser de 2 a { $max }
dynamics-torques-count = debe tener de 1 a { $max } elementos
dynamics-inertia-required = obligatorio con "torques": el momento de inercia reducido I*(φ), kg·m²
dynamics-at-most-seconds = debe ser como mucho { $max } s
dynamics-max-duration = solo se aplica con "until_angle" (lo más que puede durar una simulación hasta un ángulo): una simulación de duración "duration" termina al cumplirla
dynamics-until-initial = debe ser distinto del ángulo inicial
dynamics-duration-or-angle = dé "duration" o bien "until_angle", no ambos
dynamics-angle-or-duration = dé "until_angle" o bien "duration", no ambos
dynamics-duration-required = obligatorio: dé "duration" (cuánto tiempo simular) o "until_angle" (el ángulo de la entrada en el que parar)
dynamics-conserve-energy = necesita que todas las cargas deriven de un potencial (resortes, fuerzas y pares constantes): /machine/loads/{ $load } es { $what }
dynamics-varying-force = una fuerza de módulo variable
dynamics-varying-torque = un par de valor variable
dynamics-damper = un amortiguador
dynamics-sliding-friction = en dinámica el rozamiento se modela en un contacto con rodadura ("rolling": true: rueda mientras |tangencial| ≤ mu·normal y desliza si no); un contacto deslizante desliza sin rozamiento: quítelo
dynamics-joint-friction = el rozamiento en los pares cinemáticos no está disponible en dinámica
dynamics-not-applicable = no se aplica a la dinámica (el movimiento es el resultado)
dynamics-initial-once = dé el estado de la primera entrada una sola vez: en "initial" o en sus "start"/"speed"
dynamics-speed-constant = debe ser una constante: la velocidad de la entrada en t = 0
dynamics-inertia-not-positive = el momento de inercia reducido no es positivo en phi = { $phi } rad
dynamics-integration = la integración falló en t = { $t } s: { $reason }
dynamics-initial = el estado inicial no se puede montar: { $reason }
dynamics-step-too-small = el paso se hizo menor que el redondeo: el movimiento se dispara ahí (un par sin límite, una inercia casi nula)
dynamics-too-many-steps = más de { $steps } pasos
dynamics-not-finite = la derivada no es finita
dynamics-singular-motion = las ecuaciones del movimiento son singulares aquí (una posición singular)
dynamics-start-singular = el inicio es una posición singular de las entradas (un punto muerto o de agarrotamiento)
dynamics-start-dof = el mecanismo tiene { $dof } grado(s) de libertad, pero { $inputs } entrada(s) nombran sus coordenadas
dynamics-start-no-mass = las ecuaciones del movimiento son singulares al inicio: algún movimiento de las entradas no mueve masa (sólidos sin masa o sin inercia donde el movimiento la necesita)

## Una leva: su seguidor, su programa, su tamaño, su velocidad y su dinámica

cam-base-or-size = dé "base_radius" o "size", no ambos
cam-base-required = dé el radio del círculo base "base_radius" de la leva, o "size" para hallar el menor
cam-size = dé "max_pressure_angle" y/o "min_curvature_radius"
cam-size-any = cualquier radio base lo cumple, hasta 0 (una leva sin cuerpo): un programa que nunca sube no tiene ángulo de presión que limitar; dé el radio base (base_radius), o dimensiónela por un radio de curvatura mínimo (min_curvature_radius)
cam-no-base = ningún radio del círculo base lo cumple: pida { $asked ->
        [angle] un ángulo de presión mayor
        [rho] un radio de curvatura menor
       *[both] un ángulo de presión mayor o un radio de curvatura menor
    }
cam-no-base-arm = ningún radio del círculo base desde el que el brazo pueda arrancar el seguidor lo cumple: pida { $asked ->
        [angle] un ángulo de presión mayor
        [rho] un radio de curvatura menor
       *[both] un ángulo de presión mayor o un radio de curvatura menor
    }, o mueva el pivote o alargue el brazo
cam-no-base-best = ningún radio del círculo base lo cumple: el menor ángulo de presión máximo que da alguno es { $angle }°, con un radio base de { $base } mm; pida al menos ese, o cambie la excentricidad del seguidor
cam-no-base-arm-best = ningún radio del círculo base desde el que el brazo pueda arrancar el seguidor lo cumple: el menor ángulo de presión máximo que da alguno es { $angle }°, con un radio base de { $base } mm; pida al menos ese, o mueva el pivote o alargue el brazo
cam-speed = debe ser mayor que 0 (el sentido lo da "direction")
cam-roller-radius = un seguidor de rodillo necesita su radio "roller_radius"
cam-roller-only = solo se aplica a un seguidor de rodillo
cam-not-oscillating = no se aplica a un seguidor oscilante
cam-not-translating = no se aplica a un seguidor de traslación
cam-needs-pivot = un seguidor oscilante necesita su "pivot" (la distancia del centro de la leva a su pivote)
cam-needs-arm = un seguidor oscilante necesita su brazo "arm" (de su pivote al centro del rodillo, o a la recta de su cara)
cam-not-negative = no debe ser negativo
cam-mu = debe ser un número finito ≥ 0
cam-friction-flat = solo se aplica a un seguidor plano (un rodillo rueda; el rozamiento de un seguidor de punta no se modela)
cam-lift-closed = debe volver a su valor inicial en una vuelta: s(0) = { $start }; s(360°) = { $end }
cam-segments-count = debe tener de 1 a { $max } tramos
cam-unknown-law = ley desconocida '{ $law }': una de { $laws }
cam-needs-lift = un tramo que se mueve necesita su elevación "lift" al final
cam-after-previous = debe estar después del final del tramo anterior, { $end } rad ({ $degrees }°)
cam-dwell = un reposo mantiene la elevación del tramo anterior
cam-full-turn = el último tramo debe terminar en 360°
cam-closed = el último tramo debe terminar con elevación 0
cam-gap = el tramo { $segment } empieza en { $start } rad donde el anterior termina en { $expected } rad
cam-jump = el tramo { $segment } empieza con elevación { $from } donde el anterior termina con { $expected }
cam-offset = la excentricidad { $offset } m no está dentro de la circunferencia primitiva (radio { $pitch } m): el eje del seguidor no corta la leva
cam-reach = un brazo de { $arm } m con el pivote a { $pivot } m del centro de la leva no puede empezar con el seguidor sobre la circunferencia de radio { $radius } m (el círculo base, más el radio del rodillo, o la distancia de la cara al pivote)
cam-below-base = la elevación baja del círculo base: s = { $lift } en θ = { $theta } rad

## Un rotor: su sólido, sus cojinetes, su giro y los instantes pedidos

rotor-components = las componentes deben ser números finitos
rotor-bearings = dos posiciones distintas y finitas a lo largo del eje
rotor-symmetric = el sólido debe ser simétrico respecto a su eje de giro (si no, su momento de inercia cambiaría en los ejes del bastidor)
rotor-inertia-finite = deben ser números finitos
rotor-principal = los momentos principales de inercia [{ $first }; { $second }; { $third }] no son los de un sólido
rotor-angles-or-times = dé como mucho uno de "angles" y "times"
rotor-instants = dé de 1 a { $max } valores
rotor-never = el bastidor nunca alcanza este ángulo
rotor-never-alias = el bastidor nunca alcanza este ángulo (los ángulos cuentan sus vueltas desde el inicio, en el sentido en que gira); pasa primero por esta posición en { $degrees }° ({ $radians } rad): escriba ese

## Un engranaje: su módulo, su número de dientes, su ángulo de presión y sus proporciones

gear-teeth = debe ser un número de 1 a 10000
gear-pressure-angle = debe estar entre 0 y 1,5 rad
gear-share = debe estar entre 0 y 5 módulos
gear-overflow = un módulo de { $module } m desborda los radios de la rueda (más allá de la doble precisión)
gear-inside-base = { $radius } m está dentro del círculo base ({ $base } m): allí no hay evolvente
gear-thickness = el espesor en { $radius } m no se puede calcular en doble precisión

## Un tren de engranajes: sus elementos, sus engranes, sus velocidades y sus pares

train-members-count = dé de 1 a { $max } elementos
train-frame-or-repeat = '{ $name }' es el bastidor o repite un elemento
train-unknown-member = elemento desconocido '{ $name }' (o 'ground')
train-meshes-count = dé de 1 a { $max } engranes
train-teeth = debe ser un número de dientes de 1 a 100000
train-mesh-wheels = un engrane necesita dos ruedas distintas en elementos que no sean su portasatélites
train-frame-torque = el par sobre el bastidor no es una incógnita del tren
train-locked = el tren no puede moverse: sus engranes bloquean todos los miembros (0 grados de libertad); un lazo impar de engranes exteriores, como tres ruedas que engranan en anillo, hace girar cada rueda en los dos sentidos a la vez
train-speeds =
    el tren tiene { $dof ->
        [one] 1 grado de libertad: dé exactamente 1 velocidad que lo fije
       *[other] { $dof } grados de libertad: dé exactamente { $dof } velocidades que lo fijen
    } (dadas: { $given })
train-inconsistent = las velocidades dadas no pueden cumplirse todas: los engranes las contradicen (residuo { $residual } rad/s)
train-torques =
    el tren tiene { $dof ->
        [one] 1 grado de libertad: pida exactamente 1 par desconocido
       *[other] { $dof } grados de libertad: pida exactamente { $dof } pares desconocidos
    } (pedidos: { $asked })
train-torques-singular = no se pueden hallar los pares desconocidos: esos elementos no reciben potencias independientes
train-degenerate = los números del tren desbordan (números de dientes, relaciones o velocidades demasiado grandes para calcular con ellos)

## Masas equivalentes de una barra

equivalent-not-negative = no debe ser negativo
equivalent-cg = debe ser [x, y], con valores finitos
equivalent-points = dé de 1 a { $max } puntos
equivalent-coordinates = las coordenadas deben ser finitas
equivalent-too-far = los puntos están demasiado lejos de G para calcular con ellos (sus distancias al cuadrado desbordan la doble precisión)

## Movilidad: un mecanismo dibujado o sus pares contados

mobility-one-of = dé "mechanism" (sin entradas) o bien "counts"
mobility-bodies = debe ser de 1 a { $max } (contando el bastidor)
mobility-pairs = debe ser de 0 a { $max }
mobility-unknown-class = clase de par desconocida '{ $class }' para un recuento { $space } (una de { $known })
mobility-planar = plano
mobility-spatial = espacial

## Una función del ángulo del ciclo: su forma, sus tramos, su tabla y su CSV

function-one-of = dé exactamente uno de "expr", "segments", "table" o "csv"
function-table-only = solo se aplica a una tabla
function-parse = la expresión no se puede leer: { $why } (en el carácter { $position })
function-segments-count = debe tener de 1 a { $max } tramos
function-segment-inside = el tramo [{ $from }; { $to }] debe estar dentro de [0; period = { $period }]
function-to-after-from = "to" debe ser mayor que "from"
function-overlaps = se solapa con el tramo { $other }
function-angles-count = debe tener de 1 a { $max } ángulos
function-rows =
    "angle" tiene { $angles ->
        [one] 1 fila
       *[other] { $angles } filas
    } pero "value" tiene { $values }
function-repeat-first = la fila del primer ángulo + el periodo debe repetir el primer valor
function-increasing = los ángulos deben ser estrictamente crecientes
function-angles-period = los ángulos deben estar en [0; period = { $period })
function-spline-rows = un spline necesita al menos 3 filas
function-csv-row = fila { $row }: { $why }
function-csv-numbers = fila { $row }: '{ $angle }', '{ $value }' no son dos números finitos
function-csv-rows = más de { $max } filas (el límite de una tabla)
function-csv-empty = no hay filas de números: dé dos columnas, ángulo y valor

## Las constantes de una petición

constants-too-many = como mucho { $max } constantes (hay { $has })
constants-not-name = '{ $name }' no es un nombre: letras, dígitos y _, sin empezar por un dígito (p. ej. F, r_crank)
constants-name-length = un nombre tiene como mucho { $max } caracteres
constants-reserved = '{ $name }' ya lo usan las expresiones (phi, t, omega, pi, e y las funciones)

## Una expresión

expression-derivative-too-large = su derivada de orden { $order } tendría más de { $max } términos: escriba la expresión de forma más compacta (una potencia como sin(theta)^16 en lugar de un producto de factores iguales)
expr-too-long = la expresión tiene { $length } caracteres; el máximo es { $max }
expr-malformed-number = número mal escrito '{ $text }'
expr-unexpected-character = carácter inesperado '{ $char }'
expr-empty = expresión vacía
expr-decimal-comma = '{ $number }' está escrito con coma decimal: en una expresión los números llevan punto (0.05), y la coma separa los argumentos de una función
expr-after-end = { $token } inesperado tras el final de la expresión
expr-too-deep = expresión anidada a más de { $max } niveles
expr-ends-early = la expresión termina donde se esperaba un valor
expr-unexpected = { $token } inesperado donde se esperaba un valor
expr-needs-parentheses = la función '{ $name }' necesita paréntesis
expr-none = ninguna
expr-unknown-name = nombre desconocido '{ $name }' (variables aquí: { $variables }; constantes: { $constants })
expr-takes-one = 1 argumento
expr-takes-two = 2 argumentos
expr-takes-at-least-two = al menos 2 argumentos
expr-arity = la función '{ $name }' lleva { $takes }, y tiene { $got }
expr-unknown-function = función desconocida '{ $name }' (las conocidas: { $known })
expr-expected = se esperaba '{ $op }'
expr-token-number = número { $value }
expr-token-name = nombre '{ $name }'
expr-token-operator = '{ $op }'
dynamics-budget = se agotó el presupuesto de cálculo de { $seconds } s en t = { $t } s de tiempo simulado tras { $steps } pasos; el movimiento es demasiado rápido para la tolerancia (¿un muelle rígido?) o la integración demasiado larga: pida una integración más corta o una tolerancia más holgada{ $hint }
dynamics-budget-dop853 = ; para una integración larga y suave con una tolerancia estricta, "integrator": "dop853" da muchos menos pasos

## Equilibrado: las masas o el cuerpo del rotor, y los planos de corrección
balancing-masses-or-rotor = da el desequilibrio como "masses" (masas puntuales) o como "rotor" (el cuerpo de una petición de rotor), uno de los dos
balancing-masses-count = da de 1 a { $max } masas puntuales
balancing-planes-count = da un plano de corrección (equilibrado estático) o dos (equilibrado dinámico)
balancing-planes-apart = los dos planos de corrección deben estar en z distintas
balancing-reactions-need = las fuerzas en los cojinetes necesitan la velocidad y la z de los cojinetes: da también "{ $field }" (o ninguno de los dos)
mechanism-spatial-point = tres coordenadas, un punto del espacio: un mecanismo espacial lleva "space": "spatial" (o una coma decimal partió un número: 0,5 se escribe 0.5 o "0,5")
joint-spatial-type = un par de los mecanismos espaciales: dé al mecanismo "space": "spatial"
joint-spatial-friction = el rozamiento no se modela en los pares espaciales
mechanism-inertia-planar = la inercia de un cuerpo plano es un número, I_G respecto a su centro de masas
mechanism-inertia-spatial = un cuerpo en el espacio necesita su tensor de inercia respecto al centro de masas: [Ixx, Iyy, Izz] o la matriz 3×3
mechanism-inertia-symmetric = debe ser una matriz 3×3 simétrica de números finitos
mechanism-inertia-physical = ningún sólido rígido tiene estos momentos: cada momento principal es al menos 0 y como mucho la suma de los otros dos
mechanism-planar-point = un punto de un mecanismo espacial tiene tres coordenadas [x, y, z]
mechanism-spatial-dimensions = un mecanismo espacial se dibuja con las coordenadas de sus puntos: "dimensions" es para el plano
mechanism-gravity-spatial = debe ser [gx, gy, gz], con valores finitos
mechanism-vector-spatial = debe ser un vector [x, y, z] finito y no nulo
joint-universal-axes = una junta universal lleva "axes": [a, b], a fijo en el primer cuerpo y b en el segundo
joint-universal-perpendicular = los dos ejes de una junta universal son perpendiculares en el dibujo
joint-planar-type = un par plano: los pares de un mecanismo espacial son revolute, prismatic, cylindrical, spherical, universal y sphere_in_cylinder
joint-not-spatial = no corresponde a los pares de un mecanismo espacial
mechanism-spatial-not-here = un mecanismo espacial lo responden /v1/mobility, /v1/kinetostatics, /v1/dynamics y la máquina de un volante (/v1/flywheel)
input-coordinate-planar = un par plano tiene una sola coordenada: "coordinate" es para los pares de un mecanismo espacial
input-spatial-joint = una entrada de un mecanismo espacial es la coordenada de un par: dé "joint" (y "coordinate" si es cilíndrico)
input-cylindrical-coordinate = un par cilíndrico tiene dos coordenadas: diga cuál, "coordinate": "rotation" o "slide"
input-spatial-coordinate = este par no tiene esa coordenada: un par de revolución gira (rotation), uno prismático desliza (slide), uno cilíndrico hace ambas cosas, uno esférico gira alrededor de su "axis"
kinetostatics-not-spatial = aún no para un mecanismo espacial
