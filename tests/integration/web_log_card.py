"""The page's "Log QSO" card in a real browser (Chromium driven by Selenium, headless, a phone's
390x844) on the simulated station tracking ISS: a QSO logged from the card is listed; Edit turns
its row into fields for the call, the grid, both reports and the note, and Save changes the stored
QSO (a new version, the satellite and the time kept); Cancel changes nothing; a refusal is shown
naming the field. No console errors, no horizontal scrolling."""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from _tbharness import SOURCE, check, poll, run_test  # noqa: E402
from _web import WebStation  # noqa: E402
from web_browser import CLOCK, browser, console_errors, no_horizontal_scroll  # noqa: E402


def rows_with(d, *words):
    """The list's rows holding all of `words` (none while the list is being rebuilt)."""
    from selenium.common.exceptions import StaleElementReferenceException
    try:
        return [r for r in d.find_elements("css selector", "#log-list tbody tr") if all(x in r.text for x in words)]
    except StaleElementReferenceException:
        return []


def field(d, label):
    return d.find_element("css selector", f'#log-list input[aria-label="{label}"]')


def after_los(d, w):
    """Issue 60, item 7: with nothing followed (multiple tracking between passes) the card has a
    satellite field, says to name one, and logs on the satellite named."""
    status, r = w.post("/api/v1/track", {"list": ["SO-50", "AO-73"]})
    check(status == 200, f"multiple tracking of SO-50 and AO-73 (neither up): {status} {r}")
    poll("nothing followed", lambda: w.status()["tracking"]["followed"] is None, 10)
    sat = d.find_element("id", "log-sat")
    poll("the field asks for a satellite", lambda: sat.get_attribute("placeholder") == "name the satellite", 10)
    d.find_element("id", "log-call").send_keys("n0sat")
    d.find_element("id", "btn-log").click()
    poll("the refusal without a satellite", lambda: "no satellite is tracked; name one" in d.find_element("id", "log-reply").text, 10)
    d.find_element("id", "log-call").clear()
    d.find_element("id", "log-call").send_keys("n0sat")
    sat.send_keys("SO-50")
    d.find_element("id", "btn-log").click()
    poll("logged on SO-50", lambda: "Logged N0SAT on SO-50" in d.find_element("id", "log-reply").text, 10)
    # SO-50 was not up: stored, and said (issue 60).
    check("SO-50 was below the horizon here" in d.find_element("id", "log-reply").text,
          f"the reply says it was not up: {d.find_element('id', 'log-reply').text}")
    check(any(q["call"] == "N0SAT" and q["sat_name"] == "SO-50" for q in w.get_json("/api/v1/log")[1]["qsos"]),
          "the QSO stored on SO-50")


def main():
    # The element refresh from the shipped file, not the network.
    w = WebStation("--elements-url", "file://" + os.path.join(os.path.abspath(SOURCE), "data", "amateur.tle"),
                   clock=CLOCK)
    d = None
    try:
        status, r = w.post("/api/v1/track", {"satellite": "ISS"})
        check(status == 200 and r["ok"], f"track ISS: {status} {r}")
        d = browser(390, 844)
        d.get(f"http://127.0.0.1:{w.port}/")
        poll("the log card", lambda: d.find_elements("id", "log-call"), 15)
        d.find_element("id", "log-call").send_keys("w1aw")
        d.find_element("id", "log-grid").send_keys("fn31")
        d.find_element("id", "btn-log").click()
        poll("the reply", lambda: "Logged W1AW on ISS FM" in d.find_element("id", "log-reply").text, 10)
        row = poll("the QSO in the list", lambda: rows_with(d, "W1AW"), 10)[0]
        check("FN31" in row.text and "ISS" in row.text, f"the row: {row.text}")
        # Edit, then Cancel: nothing changes.
        row.find_element("xpath", ".//button[text()='Edit']").click()
        field(d, "Call of QSO 1").clear()
        field(d, "Call of QSO 1").send_keys("K9XX")
        d.find_element("xpath", "//table[@id='log-list']//button[text()='Cancel']").click()
        row = poll("the row back", lambda: rows_with(d, "W1AW"), 10)[0]
        check(w.get_json("/api/v1/log")[1]["qsos"][0]["version"] == 1, "Cancel stored nothing")
        # A refusal names the field and stores nothing.
        row.find_element("xpath", ".//button[text()='Edit']").click()
        field(d, "Grid of QSO 1").clear()
        field(d, "Grid of QSO 1").send_keys("FN3")
        d.find_element("xpath", "//table[@id='log-list']//button[text()='Save']").click()
        poll("the refusal", lambda: d.find_element("id", "log-reply").text.startswith("grid: 'FN3'"), 10)
        check(w.get_json("/api/v1/log")[1]["qsos"][0]["grid"] == "FN31", "the refused edit stored nothing")
        # Every field of the row, saved.
        for label, value in (("Call", "k1jt"), ("Grid", "fn20xr"), ("RST sent", "57"), ("RST rcvd", "55"),
                             ("Note", "QRP, first ISS")):
            field(d, f"{label} of QSO 1").clear()
            field(d, f"{label} of QSO 1").send_keys(value)
        no_horizontal_scroll(d, "the edit row on a phone")
        d.find_element("xpath", "//table[@id='log-list']//button[text()='Save']").click()
        poll("the change said", lambda: d.find_element("id", "log-reply").text == "QSO 1 changed", 10)
        q = w.get_json("/api/v1/log")[1]["qsos"][0]
        check((q["call"], q["grid"], q["rst_sent"], q["rst_rcvd"], q["note"], q["version"], q["sat_name"]) ==
              ("K1JT", "FN20xr", "57", "55", "QRP, first ISS", 2, "ISS"), f"the edited QSO: {q}")
        poll("the list shows the edit", lambda: rows_with(d, "K1JT", "FN20xr"), 10)
        after_los(d, w)
        errors = console_errors(d)
        check(not [e for e in errors if "409" not in e.get("message", "")], f"console errors: {errors}")
    finally:
        if d:
            d.quit()
        w.stop()


if __name__ == "__main__":
    run_test(main)
