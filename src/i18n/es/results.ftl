# Lo que un resultado dice de sí mismo: sus avisos y cómo se estimó su
# precisión, en español (inglés en ../en/results.ftl, con los mismos
# identificadores y argumentos).

## Cualquier tipo

warning-constant-unused = la constante { $name } no la usa ninguna expresión de la petición
warning-at-field = { $pointer }: { $said }

## Una integración en el tiempo que se detuvo

warning-ode-step-too-small = el paso de integración bajó del error de redondeo en t = { $t } s
warning-ode-too-many-steps = más de { $steps } pasos
warning-ode-not-finite = la derivada no es finita en t = { $t } s

## Volante

accuracy-flywheel = M* integrado a trozos entre sus puntos de ruptura: Gauss-Kronrod 7/15 adaptativo para las expresiones, exacto (Simpson en cada trozo polinómico) para las tablas; cambios de signo acotados con 1024 muestras por ciclo y localizados por el método de Brent; inercia exacta a partir de los extremos de (1±eps/2)^2 I*(phi) - F(phi) en los extremos de los trozos y en los puntos estacionarios (forma cerrada cuando I* es constante); comprobación por integración en el tiempo (Dormand-Prince 5(4)) de la ecuación del movimiento
warning-train-assembly = el satélite { $planet } no se puede montar con un mismo módulo: su corona tiene { $ring } dientes, pero el planeta ({ $sun }) y el satélite piden una corona de { $fits } (z_corona = z_planeta + 2 z_satélite en un satélite simple)
warning-flywheel-net-work = el trabajo neto en un ciclo es { $net } J, dentro de la tolerancia; las cargas se usan tal como se dan
warning-flywheel-check = la comprobación por simulación en el tiempo no terminó: { $why }
warning-flywheel-degenerate = M* es idénticamente nulo e I* constante: la velocidad es constante con cualquier inercia, así que no hace falta volante
warning-flywheel-no-disk = sin disco: la inercia de volante necesaria es { $inertia } kg*m^2 (la inercia propia de la máquina ya mantiene el grado de irregularidad dentro de lo pedido)

## Un mecanismo

warning-sketch-larger = los puntos del croquis están unas { $ratio } veces más separados de lo que los colocan las dimensiones: los números sin unidad, en `points` y en el `cg` de un cuerpo, se leen en metros (para milímetros escriba "40 mm"), y un centro de masas dibujado así queda otro tanto más lejos de su cuerpo
warning-sketch-smaller = los puntos del croquis están unas { $ratio } veces más juntos de lo que los colocan las dimensiones: revise las unidades de las dimensiones ("100 mm", no "100 m")
warning-dimensions-free = las dimensiones dejan libres algunos puntos: quedan tan cerca del croquis como permiten los demás
warning-span = { $from } a { $to }
warning-at-time = t = { $t } s
warning-contact-off-end = contacto { $name }: el contacto sale por el extremo de una curva abierta en { $at }: ahí los resultados no son los de un contacto (prolongue la curva)
warning-contact-jumped = contacto { $name }: el contacto saltó en { $at } a un punto lejos de donde se seguía (otro lóbulo): el seguidor deja la curva en la que estaba y cae en otro sitio, un salto que el movimiento ahí no muestra
warning-contact-cut = contacto { $name }: los sólidos se cortan en { $at } (el `penetration` de cada paso dice cuánto): el contacto que siguen las ecuaciones ahí es imposible y no se encontró otro fuera de ambos sólidos (un contacto con rodadura no puede saltar a otro lóbulo; una leva demasiado cóncava para su seguidor)
warning-contact-slipping = el contacto { $name } desliza de { $at }: μN no cubre el rozamiento que la rodadura necesitaría ahí, y actúa el rozamiento cinético (el `state` del contacto de cada muestra lo dice)
warning-contact-overlap = contacto { $name }: las curvas se solapan alrededor del contacto en { $at }: ahí los sólidos se tocarían en otro punto (el seguidor salta a otro lóbulo: una cara plana en un tramo cóncavo, un rodillo en un hueco más cerrado); los resultados ahí siguen un contacto imposible
warning-contact-separates = contacto { $name }: la fuerza normal es negativa en { $at }: ahí los sólidos se separarían (un salto del seguidor, un disco que deja su pista) salvo que algo los mantenga juntos
warning-contact-slips = contacto { $name }: la rodadura necesita más rozamiento del que da mu = { $mu } en { $at } (vea mu_required): ahí deslizaría

## Dinámica directa

accuracy-dynamics = { $integrator } con salida densa, eventos localizados sobre ella por el método de Brent; trabajo { $work }{ $repeated }
accuracy-work-quadrature = por cuadratura adaptativa en el ángulo
accuracy-work-power = como integral de la potencia
accuracy-integrator-stiff = { $name } (el par explícito elegido primero encontró el modelo rígido (stiff) en t = { $t } s: sus pasos los limitaba la estabilidad, no la precisión; se repitió la integración desde el principio)
accuracy-repeated = ; la integración llegó a su ángulo tras más pasos de los que guarda un trabajo ({ $mib } MiB de ellos) y se repitió hasta el tiempo final hallado, para las muestras (los pasos y evaluaciones cuentan ambas)
accuracy-dynamics-mechanism = { $integrator } sobre las ecuaciones del movimiento de índice 1 [M Φ_qᵀ; Φ_q 0], { $form }; el estado proyectado sobre Φ = 0 y Φ_q·q̇ = 0{ $energy } tras cada paso; en LU, las filas de Φ_q a menos de 1e-5 de la dependencia se mantienen en las posiciones singulares y las dependientes se descartan; eventos por el método de Brent sobre la salida densa; trabajo como integral de la potencia{ $repeated }
accuracy-form-sparse-held = resueltas por el método del espacio imagen (LDLᵀ dispersa de Φ_q M⁻¹ Φ_qᵀ; en las posiciones singulares se mantienen las combinaciones que dejan las filas cuyos senos de pivote caen de 1e-3 a 3e-4, por LU a ~1e-8 de la dependencia)
accuracy-form-sparse = resueltas por el método del espacio imagen (LDLᵀ dispersa de Φ_q M⁻¹ Φ_qᵀ) lejos de las posiciones singulares y por LU cerca de ellas (los pasos fallaron donde la forma dispersa mantenía los pliegues)
accuracy-form-lu = resueltas por LU
accuracy-energy-held = { " " }y, al tener potencial las cargas, sobre T + V = E₀ ({ $held } de { $steps } pasos)
warning-dynamics-not-reached = no se alcanzó el ángulo { $angle } en { $time }
warning-dynamics-contact-open-at-start = el contacto '{ $name }' tira al comienzo: su fuerza normal ahí es menor que 0, y un contacto solo empuja — los sólidos se separan en el acto (la gravedad o las cargas los apartan): la integración se detiene en t = 0
warning-dynamics-contact-opens = el contacto '{ $name }' se abre en { $t }: su fuerza normal cae a 0 y los sólidos se separarían (lo que sigue no es el movimiento de estos pares): la integración se detiene ahí
warning-dynamics-unexpected-guard = la integración se detuvo donde el modelo no cambia nada (una condición cruzó donde el modelo no tiene ninguna)
warning-dynamics-turns-unlisted = las primeras { $listed } vueltas se listan como eventos; después se cruzaron { $more } más, que no se listan
warning-dynamics-branch-left = el balance de energía falla desde { $t } (residuo { $residual }, mayor que { $bound }), después de que el movimiento pasara cerca de una posición singular en { $at }: el mecanismo puede haber cambiado allí de rama (plegado en otro modo de montaje), y su movimiento a partir de entonces no es fiable; vea machine.near_singular y samples[].energy_residual
warning-dynamics-integrator-replaced = el integrador pedido, "{ $asked }", llegó a una posición singular en { $t }, donde sus pasos sacan al mecanismo de su rama (podría plegarse en otro modo de montaje): se repitió la integración desde el principio con Dormand-Prince 5(4) ("dopri5"), que lo mantiene en su rama; vea accuracy.integrator_replaced_at
warning-dynamics-near-singular = el movimiento pasó cerca de posiciones singulares (el jacobiano de los pares casi perdió rango) { $count ->
        [one] una vez
       *[other] { $count } veces
    }, la primera en { $first }: el mecanismo se mantuvo en su rama; vea machine.near_singular

## Cinetostática

accuracy-kinetostatics = coordenadas de los sólidos; { $assembly }; velocidades y aceleraciones a partir del jacobiano de las restricciones; multiplicadores de Phi_q^T lambda = Q - M q'' para las reacciones y las acciones motoras, comprobados con la potencia virtual
accuracy-assembly-closed-form = posiciones en forma cerrada (una manivela y díadas: intersecciones circunferencia-circunferencia y circunferencia-recta, en la rama dibujada), confirmadas por Newton-Raphson
accuracy-assembly-newton = montaje por Newton-Raphson con continuación de hasta tercer orden
warning-redundant-constraints = { $count ->
        [one] una restricción redundante
       *[other] { $count } restricciones redundantes
    }: las reacciones de los pares { $joints } no las determina el equilibrio y se dan como nulas

## Levas

accuracy-cam = las leyes en forma cerrada y sus derivadas hasta el tirón; la curva primitiva y el perfil a partir de la posición del seguidor en la referencia de la leva, su curvatura con derivadas exactas (la de una cara plana ρ = R_b + s + s″; la de una cara oscilante como envolvente de sus rectas); fuerzas de la ecuación del seguidor según su eje (respecto a su pivote, si oscila)
warning-cam-velocity = velocidad
warning-cam-acceleration = aceleración
warning-cam-sense = no se dio el sentido de giro de la leva ("direction"): gira en sentido antihorario ("ccw"); con un seguidor excéntrico u oscilante, el sentido cambia el ángulo de presión y el radio hallado
warning-cam-fundamental-law = la ley fundamental del diseño de levas no se cumple en { $at }°: la { $what } salta { $jump } { $unit }/rad^{ $order }
warning-cam-undercut = socavado: el perfil se pliega sobre sí mismo cerca de { $at }° (radio de curvatura { $rho } m): un círculo base mayor o un rodillo menor
warning-cam-undercut-flat = socavado: el perfil se pliega sobre sí mismo cerca de { $at }° (radio de curvatura { $rho } m): un círculo base mayor
warning-cam-pressure-translating = el ángulo de presión llega a { $max }° en { $at }° (más de { $limit }° para un seguidor de traslación): un círculo base mayor, o una excentricidad
warning-cam-pressure-oscillating = el ángulo de presión llega a { $max }° en { $at }° (más de { $limit }° para un seguidor oscilante): un círculo base mayor, u otro pivote
warning-cam-separation = el seguidor se separaría de la leva en { $at } (fuerza de contacto negativa)
warning-dynamics-chatter = los contactos pasaron de rodar a deslizar y al revés { $count } veces hasta { $t } (vibran): la integración se detiene ahí

## Movilidad

warning-mobility-grubler = el criterio de Grübler da { $grubler } pero el dibujo se mueve con { $dof }: { $count ->
        [one] una restricción repite
       *[other] { $count } restricciones repiten
    } lo que imponen las demás (una geometría especial, como barras paralelas), y el recuento no las ve
mobility-counts-inputs = { $inputs ->
        [one] una coordenada de entrada describe
       *[other] { $inputs } coordenadas de entrada describen
    } el movimiento (con una, sirve cualquier coordenada que se mueva: un ángulo, un desplazamiento); qué pares pueden servir juntos depende de la geometría, que los recuentos solos no dicen: envíe el dibujo del mecanismo para sus entradas posibles

## La corrección de las respuestas de los alumnos

check-no-answer = sin respuesta
check-not-a-number = { $value } no es un número
check-wrong-dimension = '{ $text }' está en { $found }, y la respuesta va en { $unit }
check-unreadable = '{ $text }' no es un número ni una magnitud ({ $why })
check-unread = { $name }: { $why }.
check-value = { $value }{ $unit }
check-given = { $text } = { $si }
check-rule-zero-level = ±{ $value } (el nivel de cero)
check-rule-absolute = ±{ $value }
check-rule-relative = { $percent } %
check-rule-sigfigs = { $count ->
        [one] una cifra significativa
       *[other] { $count } cifras significativas
    }
check-correct-revealed = { $name }: correcto ({ $given }, dentro de { $within } de { $expected }).
check-correct = { $name }: correcto (dentro de { $within }).
check-off = , desviado un { $percent } %
check-wrong-revealed = { $name }: { $given } no está dentro de { $within } del valor esperado, { $expected }{ $off }.
check-wrong = { $name }: { $given } no está dentro de { $within } del valor esperado.
check-with-slip = { $feedback } { $slip }
check-slip-other-value = Coincide con { $other } del resultado: ¿se dio ese valor como { $name }?
check-slip-reaction-sign = Tiene el signo contrario: ¿la reacción sobre el otro sólido del par? (El resultado da la fuerza sobre el segundo sólido del par.)
check-slip-sign = Tiene el signo contrario.
check-slip-degrees = Coincide con el valor en grados: se espera en radianes.
check-slip-rpm = Coincide con el valor en rpm: se espera en rad/s (1 rpm = 2π/60 rad/s).
check-slip-times-2pi = Es 2π veces el valor esperado.
check-slip-over-2pi = Es el valor esperado dividido entre 2π.
check-slip-power-of-ten = Es 10^{ $k } veces el valor esperado: ¿un prefijo de unidad (mm por m, kN por N)?
check-summary = { $passed } de { $total } respuestas dentro de la tolerancia (corregido por mechdyn { $version }).

## Rotores, engranajes, trenes de engranajes, masas equivalentes

accuracy-rotor = Newton F = [dQ/dt]_rel + Ω×Q y Euler M_G = [dK_G/dt]_rel + Ω×K_G en los ejes de la referencia; fuerzas en los cojinetes y momento motor de las seis ecuaciones de equilibrio, en forma cerrada
accuracy-gear-train = fórmula de Willis en cada engrane respecto a su portasatélites; pares por potencia virtual sobre una base de los movimientos virtuales del tren (espacio nulo por SVD)
warning-gear-pointed = el diente acaba en punta antes de { $radius } m: su espesor ahí sería { $thickness } m
warning-gear-module-metres = un módulo de { $module } m: un número sin unidad está en el SI (metros); para { $module } mm escriba "{ $module } mm" (los módulos de más de { $plausible } m son raros)
warning-equivalent-incomplete = ningún conjunto de masas en estos puntos reproduce a la vez la masa, el centro de masas y la inercia; el ajuste por mínimos cuadrados deja un residuo relativo de { $residual }
warning-equivalent-not-unique = los puntos no determinan las masas; se da el conjunto más pequeño (de norma mínima)

## Equilibrado
accuracy-balancing-static = equilibrado estático en un plano: la corrección C₁ = −U anula el desequilibrio estático U = Σ m·r·e^(iθ); el par queda; forma cerrada
accuracy-balancing-dynamic = equilibrado dinámico en dos planos: C₁ + C₂ = −U y (z₂ − z₁)·C₂ = −D(z₁), D(z₁) = Σ m·r·(z − z₁)·e^(iθ); forma cerrada
warning-balancing-planes-close = los planos de corrección distan solo { $gap } m, 1/{ $ratio } de la longitud del rotor de { $span } m (sus masas, cojinetes y planos): las dos correcciones crecen como 1/(z₂ − z₁), aquí hasta { $mass } kg; separe más los planos
warning-balancing-couple-left = un solo plano de corrección elimina solo el desequilibrio estático: queda un desequilibrio dinámico de { $couple } kg·m² (da dos planos para eliminarlo)
accuracy-global-made = una cota del error global: 1,5 veces la mayor diferencia del ángulo en las muestras respecto al mismo cálculo con una tolerancia cien veces menor (global_error), o la suma de los errores locales estimados si es mayor
accuracy-global-none = la suma de los errores locales estimados, que no tiene en cuenta cómo crecen los errores a lo largo del movimiento (un movimiento caótico o largo puede estar mucho más lejos): no se hizo el cálculo con una tolerancia cien veces menor, porque { $why }
accuracy-global-to-angle = el cálculo termina en un ángulo, en otro instante cada vez
accuracy-global-floor = la tolerancia ya está cerca del límite de la doble precisión
accuracy-global-budget = el cálculo llevó más de la cuarta parte del presupuesto de cálculo (suba --job-seconds o acorte el movimiento)
accuracy-global-failed = el cálculo más estricto falló o se detuvo en otro punto
accuracy-kinetostatics-spatial = posiciones por Newton–Raphson sobre las ecuaciones de los pares (cuaterniones girados por incrementos de rotación) hasta |Φ| ≤ 1e-12 del tamaño del dibujo, velocidades y aceleraciones de Φ_q·v = −Φ_t y Φ_q·a = γ, reacciones y esfuerzos de las ecuaciones de Newton–Euler con Φ_qᵀ·λ (de norma mínima donde las ecuaciones se repiten); la potencia virtual de las acciones los comprueba
warning-redundant-constraints-spatial = { $count ->
        [one] una restricción redundante
       *[other] { $count } restricciones redundantes
    }: el equilibrio no determina las reacciones de los pares { $joints }; se da de cada una el reparto de norma mínima, marcado "determinate": false
accuracy-dynamics-spatial = las ecuaciones de Newton–Euler de cada sólido respecto a su centro de masas con las filas de los pares, [M Φ_qᵀ; Φ_q 0] resuelto por LU en cada evaluación (orientaciones como cuaterniones unitarios, el jacobiano sobre incrementos de giro), integradas sobre las posiciones, cuaterniones y velocidades de los sólidos; tras cada paso, los cuaterniones normalizados y el estado proyectado sobre Φ = 0 y Φ_q·v = 0; eventos por el método de Brent sobre la salida densa; trabajo como potencia integrada; reacciones de las ecuaciones de Newton–Euler del movimiento hallado
warning-dynamics-redundant-spatial = { $count ->
        [one] una fila de restricción repite otras al inicio (como en el mecanismo de Bricard) y se dejó
       *[other] { $count } filas de restricción repiten otras al inicio (como en el mecanismo de Bricard) y se dejaron
    } fuera de las ecuaciones del movimiento; las reacciones que comparten se dan como el reparto de norma mínima, marcadas "determinate": false
