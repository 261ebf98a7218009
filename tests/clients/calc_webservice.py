"""A real LibreOffice Calc, headless, fetches answers with WEBSERVICE().

Driven through UNO (Debian's python3-uno): a new spreadsheet gets the P.103
flywheel's parameters in cells and formulas that call the running service's
template GET; Calc recalculates and fetches; the script prints what the cells
hold, as JSON, for the Rust test to check (tests/api/libreoffice.rs).

Usage: /usr/bin/python3 calc_webservice.py BASE_URL PROFILE_DIR [SAVE_AS.fods]
(with SAVE_AS, the sheet is also saved: examples/p103-flywheel.fods is made so)
"""
import json
import os
import subprocess
import sys
import time

import uno
from com.sun.star.beans import PropertyValue

BASE, PROFILE = sys.argv[1], sys.argv[2]
PORT = 2002 + os.getpid() % 1000


def prop(name, value):
    p = PropertyValue()
    p.Name, p.Value = name, value
    return p


office = subprocess.Popen([
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
    # The lab's table: parameters in cells, the service's address in one cell.
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
    started = time.time()
    doc.calculateAll()
    elapsed = time.time() - started
    out = {name: cell(name).Value for name in ["B5", "B6", "B7"]}
    out["B8"] = cell("B8").String
    out["errors"] = {name: cell(name).getError() for name in ["B5", "B6", "B7", "B8"]}
    out["seconds"] = elapsed
    out["study"] = [cell(f"B{row}").Value for row in range(11, 16)]
    if len(sys.argv) > 3:
        target = uno.systemPathToFileUrl(os.path.abspath(sys.argv[3]))
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
