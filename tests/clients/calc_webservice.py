"""A real LibreOffice Calc, headless, fetches answers with WEBSERVICE().

Driven through UNO (Debian's python3-uno): a new spreadsheet gets the P.103
flywheel's parameters in cells and formulas that call the running service's
template GET; Calc recalculates and fetches; the script prints what the cells
hold, as JSON, for the Rust test to check (tests/api/libreoffice.rs).

Usage: /usr/bin/python3 calc_webservice.py [--es] BASE_URL PROFILE_DIR [SAVE_AS.fods]
(with SAVE_AS, the sheet is also saved: examples/p103-flywheel.fods is made so)

With --es, Calc runs in Spanish with the es-ES locale (Debian's
libreoffice-l10n-es): the formulas are typed with their Spanish names
(VALOR, SERVICIOWEB; `;` between arguments), the sheet writes its
parameters with decimal commas itself (every digit: B3&"") and asks for
`decimal=comma`, and an error's reason in Spanish with `lang=es&errors=text`
(examples/p103-flywheel-es.fods is made so).
"""
import json
import os
import subprocess
import sys
import time

import uno
from com.sun.star.beans import PropertyValue

SPANISH = sys.argv[1] == "--es"
ARGS = sys.argv[2:] if SPANISH else sys.argv[1:]
BASE, PROFILE = ARGS[0], ARGS[1]
PORT = 2002 + os.getpid() % 1000

# The profile's settings before Calc starts: its interface and locale in Spanish.
SPANISH_PROFILE = """<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry" xmlns:xs="http://www.w3.org/2001/XMLSchema"
 xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Setup/L10N"><prop oor:name="ooLocale" oor:op="fuse"><value>es</value></prop></item>
<item oor:path="/org.openoffice.Setup/L10N"><prop oor:name="ooSetupSystemLocale" oor:op="fuse"><value>es-ES</value></prop></item>
</oor:items>
"""
if SPANISH:
    os.makedirs(os.path.join(PROFILE, "user"), exist_ok=True)
    with open(os.path.join(PROFILE, "user", "registrymodifications.xcu"), "w") as f:
        f.write(SPANISH_PROFILE)


def prop(name, value):
    p = PropertyValue()
    p.Name, p.Value = name, value
    return p


def english_sheet(cell):
    """The lab's table: parameters in cells, the service's address in one cell."""
    cell("A1").String, cell("B1").String = "service", BASE
    cell("A2").String, cell("B2").Value = "F (N*m)", 1200
    cell("A3").String, cell("B3").Value = "eps", 0.03
    url = '$B$1&"/v1/templates/p103-slider-flywheel/result/'
    query = '?F="&B2&"&eps="&B3'
    cell("A5").String = "I exact (kg*m^2)"
    cell("B5").Formula = f'=VALUE(WEBSERVICE({url}inertia_exact{query}))'
    cell("A6").String = "I approximate (kg*m^2)"
    cell("B6").Formula = f'=VALUE(WEBSERVICE({url}inertia_approximate{query}))'
    cell("A7").String = "I exact (slug*ft^2)"
    cell("B7").Formula = f'=VALUE(WEBSERVICE({url}inertia_exact{query}&"&unit=slug*ft%5E2"))'
    cell("A8").String = "text of B5's call"
    cell("B8").Formula = f'=WEBSERVICE({url}inertia_exact{query})'
    # A parameter study in the sheet: I exact against F, one call per row.
    cell("A10").String, cell("B10").String = "F (N*m)", "I exact (kg*m^2)"
    for k, f in enumerate([500, 750, 1000, 1250, 1500]):
        row = 11 + k
        cell(f"A{row}").Value = f
        cell(f"B{row}").Formula = f'=VALUE(WEBSERVICE({url}inertia_exact?F="&A{row}&"&eps="&$B$3))'


def spanish_sheet(cell):
    """The same table as a Spanish lab types it: Spanish function names and
    `;` (FormulaLocal), the parameters written by the sheet with decimal
    commas (F = 1200,5 by concatenation, ε = 0,03 by TEXTO), the answers
    asked with decimal commas for VALOR to read."""
    cell("A1").String, cell("B1").String = "servicio", BASE
    cell("A2").String, cell("B2").Value = "F (N*m)", 1200.5
    cell("A3").String, cell("B3").Value = "eps", 0.03
    url = '$B$1&"/v1/templates/p103-slider-flywheel/result/'
    # The sheet writes each number with every digit and its decimal comma
    # (B3&"": "0,03"; TEXTO(B3;"0,00") rounded ε = 0,025 to 0,03).
    query = '?F="&B2&"&eps="&B3&"&decimal=comma&lang=es'
    cell("A5").String = "I exacta (kg*m^2)"
    cell("B5").FormulaLocal = f'=VALOR(SERVICIOWEB({url}inertia_exact{query}"))'
    cell("A6").String = "I aproximada (kg*m^2)"
    cell("B6").FormulaLocal = f'=VALOR(SERVICIOWEB({url}inertia_approximate{query}"))'
    cell("A7").String = "I exacta (slug*ft^2)"
    cell("B7").FormulaLocal = f'=VALOR(SERVICIOWEB({url}inertia_exact{query}&unit=slug*ft%5E2"))'
    cell("A8").String = "texto de la llamada de B5"
    cell("B8").FormulaLocal = f'=SERVICIOWEB({url}inertia_exact{query}")'
    cell("A9").String = "sin decimal=comma: VALOR lee mal el punto"
    cell("B9").FormulaLocal = f'=VALOR(SERVICIOWEB({url}inertia_exact?F="&B2&"&eps="&TEXTO(B3;"0,00")))'
    cell("A10").String, cell("B10").String = "F (N*m)", "I exacta (kg*m^2)"
    for k, f in enumerate([500, 750, 1000, 1250, 1500]):
        row = 11 + k
        cell(f"A{row}").Value = f
        cell(f"B{row}").FormulaLocal = (
            f'=VALOR(SERVICIOWEB({url}inertia_exact?F="&A{row}&"&eps="&$B$3&"&decimal=comma"))'
        )
    # Every digit reaches the service: ε = 0,025, read back as the irregularity the flywheel keeps.
    cell("A17").String, cell("C17").Value = "eps = 0,025", 0.025
    cell("B17").FormulaLocal = f'=VALOR(SERVICIOWEB({url}check/irregularity?F="&B2&"&eps="&C17&"&decimal=comma"))'
    # An error reaches the cell as its reason, in Spanish (errors=text), not as #¡VALOR!.
    cell("A18").String = "ε = 3: el motivo"
    cell("B18").FormulaLocal = f'=SERVICIOWEB({url}inertia_exact?F="&B2&"&eps=3&decimal=comma&lang=es&errors=text")'
    # The README's recipe: the number where there is one, else the reason (not Err:502).
    refused = f'SERVICIOWEB({url}inertia_exact?F="&B2&"&eps="&C19&"&decimal=comma&lang=es&errors=text")'
    cell("A19").String, cell("C19").Value = "ε = 3 con SI.ERROR", 3
    cell("B19").FormulaLocal = f'=SI.ERROR(VALOR({refused});{refused})'


# Calc's interface language comes from the environment at its first start
# (the profile's ooLocale alone is reset to en-US).
SPANISH_ENV = dict(os.environ, LANGUAGE="es", LANG="es_ES.UTF-8", LC_ALL="es_ES.UTF-8")
office = subprocess.Popen(env=SPANISH_ENV if SPANISH else None, args=[
    "soffice", "--headless", "--invisible", "--norestore", "--nologo", "--nodefault",
    f"-env:UserInstallation=file://{PROFILE}",
    f"--accept=socket,host=127.0.0.1,port={PORT};urp;StarOffice.ComponentContext",
], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
try:
    local = uno.getComponentContext()
    resolver = local.ServiceManager.createInstanceWithContext("com.sun.star.bridge.UnoUrlResolver", local)
    for _ in range(600):
        try:
            context = resolver.resolve(f"uno:socket,host=127.0.0.1,port={PORT};urp;StarOffice.ComponentContext")
            break
        except Exception:
            time.sleep(0.1)
    else:
        sys.exit("LibreOffice did not start")
    desktop = context.ServiceManager.createInstanceWithContext("com.sun.star.frame.Desktop", context)
    doc = desktop.loadComponentFromURL("private:factory/scalc", "_blank", 0, (prop("Hidden", True),))
    sheet = doc.Sheets.getByIndex(0)
    cell = sheet.getCellRangeByName
    if SPANISH:
        spanish_sheet(cell)
    else:
        english_sheet(cell)
    started = time.time()
    doc.calculateAll()
    elapsed = time.time() - started
    out = {name: cell(name).Value for name in ["B5", "B6", "B7"]}
    out["B8"] = cell("B8").String
    out["errors"] = {name: cell(name).getError() for name in ["B5", "B6", "B7", "B8"]}
    out["seconds"] = elapsed
    out["study"] = [cell(f"B{row}").Value for row in range(11, 16)]
    out["B9"] = cell("B9").String
    out["B9_error"] = cell("B9").getError()
    out["decimal_separator"] = cell("B3").String
    if SPANISH:
        out["B17"] = cell("B17").Value
        out["B18"] = cell("B18").String
        out["B19"] = cell("B19").String
        out["errors"].update({name: cell(name).getError() for name in ["B17", "B18", "B19"]})
    if len(ARGS) > 2:
        target = uno.systemPathToFileUrl(os.path.abspath(ARGS[2]))
        doc.storeToURL(target, (prop("FilterName", "OpenDocument Spreadsheet Flat XML"),))
    doc.close(True)
    print(json.dumps(out))
finally:
    try:
        desktop.terminate()
    except Exception:
        pass
    try:
        office.wait(timeout=20)
    except subprocess.TimeoutExpired:
        office.kill()
