// Malformed contact input: every case must name the file, the line and the keyword.
#include "bad_deck.hpp"
#include "deck_fixtures.hpp"

namespace kontakt::inp::test {

namespace {

/// Appends `tail` to the two cubes with their contact surfaces: its first line is line 33.
std::string surfaces_plus(const std::string& tail) { return two_cubes_surfaces() + tail; }

/// A deck whose first material has no *ELASTIC: the E-derived defaults cannot be resolved.
std::string first_material_without_elastic() {
  std::string deck = two_cubes_surfaces();
  const std::string steel = "*MATERIAL, NAME=STEEL\n";
  deck.insert(deck.find(steel), "*MATERIAL, NAME=AIR\n*DENSITY\n1.\n");
  return deck + linear_interaction();  // its *SURFACE BEHAVIOR is on line 37
}

}  // namespace

std::vector<BadDeck> contact_bad_decks() {
  const std::string si = linear_interaction();  // three lines
  const std::string s2s = "*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE";
  const std::string nts = "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE";
  const std::string step = "*STEP\n*STATIC\n";
  const std::string interaction = "*SURFACE INTERACTION, NAME=SI\n";
  const std::string behavior = interaction + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=";
  return {
      // *CONTACT PAIR
      {"pair without type", surfaces_plus("*CONTACT PAIR, INTERACTION=SI\nSLAVE, MASTER\n" + si),
       33, "*CONTACT PAIR", "TYPE= is required"},
      {"mortar pair",
       surfaces_plus("*CONTACT PAIR, INTERACTION=SI, TYPE=MORTAR\nSLAVE, MASTER\n"), 33,
       "*CONTACT PAIR", "TYPE=MORTAR is not supported"},
      {"unknown pair type",
       surfaces_plus("*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO NODE\nSLAVE, MASTER\n"), 33,
       "*CONTACT PAIR", "TYPE=NODETONODE: expected"},
      {"mixed pair types",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + nts + "\nSLAVENODES, MASTER\n"), 38,
       "*CONTACT PAIR", "may not mix contact types"},
      {"linear pair option", surfaces_plus(s2s + ", LINEAR\nSLAVE, MASTER\n"), 33,
       "*CONTACT PAIR", "LINEAR"},
      {"pair without data line", surfaces_plus(s2s + "\n" + si), 33, "*CONTACT PAIR",
       "expected at least 1 data line"},
      {"pair with one surface", surfaces_plus(s2s + "\nSLAVE\n"), 34, "*CONTACT PAIR",
       "expected at least 2 field(s)"},
      {"undefined interaction",
       surfaces_plus("*CONTACT PAIR, INTERACTION=NOPE, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n"),
       34, "*CONTACT PAIR", "surface interaction NOPE is not defined"},
      {"interaction without behavior", surfaces_plus(interaction + s2s + "\nSLAVE, MASTER\n"),
       33, "*SURFACE INTERACTION", "no *SURFACE BEHAVIOR"},
      {"undefined slave surface", surfaces_plus(si + s2s + "\nNOPE, MASTER\n"), 37,
       "*CONTACT PAIR", "slave surface NOPE is not defined"},
      {"empty slave surface",
       surfaces_plus("*SURFACE, NAME=EMPTY\n" + si + s2s + "\nEMPTY, MASTER\n"), 38,
       "*CONTACT PAIR", "slave surface EMPTY is empty"},
      {"node slave for surface to surface", surfaces_plus(si + s2s + "\nSLAVENODES, MASTER\n"),
       37, "*CONTACT PAIR", "SLAVENODES is a node surface"},
      {"node master surface", surfaces_plus(si + nts + "\nSLAVE, SLAVENODES\n"), 37,
       "*CONTACT PAIR", "master surface SLAVENODES must be made of element faces"},
      {"face scheme on a node slave",
       surfaces_plus(si + nts + ", SCHEME=gc3\nSLAVENODES, MASTER\n"), 37, "*CONTACT PAIR",
       "SCHEME=gc3 integrates over slave faces"},
      {"unknown scheme", surfaces_plus(s2s + ", SCHEME=mortar\nSLAVE, MASTER\n"), 33,
       "*CONTACT PAIR", "SCHEME=MORTAR is not a contact scheme"},
      {"negative adjust", surfaces_plus(s2s + ", ADJUST=-0.1\nSLAVE, MASTER\n"), 33,
       "*CONTACT PAIR", "must not be negative"},
      {"undefined adjust set", surfaces_plus(si + s2s + ", ADJUST=NOSET\nSLAVE, MASTER\n"), 37,
       "*CONTACT PAIR", "ADJUST node set NOSET is not defined"},
      {"small sliding with a value", surfaces_plus(nts + ", SMALL SLIDING=YES\nSLAVE, MASTER\n"),
       33, "*CONTACT PAIR", "takes no value"},
      {"pair in a step", surfaces_plus(step + s2s + "\nSLAVE, MASTER\n*END STEP\n"), 35,
       "*CONTACT PAIR", "not allowed within a step"},
      {"tied node to surface",
       surfaces_plus(behavior + "TIED\n1e7\n*FRICTION\n0.1, 1e5\n" + nts + "\nSLAVE, MASTER\n"),
       39, "*CONTACT PAIR", "only available for SURFACE TO SURFACE"},
      {"node to surface without tension",
       surfaces_plus(behavior + "LINEAR\n1e7, 1e-40\n" + nts + "\nSLAVE, MASTER\n"), 37,
       "*CONTACT PAIR", "above 1e-30"},
      // *SURFACE INTERACTION, *SURFACE BEHAVIOR
      {"duplicate interaction", surfaces_plus(si + "*SURFACE INTERACTION, NAME=si\n"), 36,
       "*SURFACE INTERACTION", "defined twice"},
      {"behavior outside an interaction",
       surfaces_plus("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e7\n"), 33,
       "*SURFACE BEHAVIOR", "must follow a *SURFACE INTERACTION"},
      {"behavior after a material",
       surfaces_plus(interaction + "*MATERIAL, NAME=X\n*SURFACE BEHAVIOR, "
                                   "PRESSURE-OVERCLOSURE=LINEAR\n"),
       35, "*SURFACE BEHAVIOR", "must follow a *SURFACE INTERACTION"},
      {"behavior without law", surfaces_plus(interaction + "*SURFACE BEHAVIOR\n1e7\n"), 34,
       "*SURFACE BEHAVIOR", "PRESSURE-OVERCLOSURE= is required"},
      {"unknown law", surfaces_plus(behavior + "SOFT\n1e7\n"), 34, "*SURFACE BEHAVIOR",
       "PRESSURE-OVERCLOSURE=SOFT"},
      {"exponential c0", surfaces_plus(behavior + "EXPONENTIAL\n0., 1.\n"), 35,
       "*SURFACE BEHAVIOR", "c0 (field 1) must be positive"},
      {"exponential p0", surfaces_plus(behavior + "EXPONENTIAL\n1e-3, -1.\n"), 35,
       "*SURFACE BEHAVIOR", "p0 (field 2) must not be negative"},
      {"exponential without data", surfaces_plus(behavior + "EXPONENTIAL\n"), 34,
       "*SURFACE BEHAVIOR", "expected at least 1 data line"},
      {"tabular decreasing", surfaces_plus(behavior + "TABULAR\n0., 0.\n1., -1.\n"), 36,
       "*SURFACE BEHAVIOR", "overclosures must increase"},
      {"tabular temperatures", surfaces_plus(behavior + "TABULAR\n0., 0., 20.\n1., 1., 100.\n"),
       36, "*SURFACE BEHAVIOR", "temperature-dependent"},
      {"linear not a number", surfaces_plus(behavior + "LINEAR\nstiff\n"), 35,
       "*SURFACE BEHAVIOR", "field 1 ('stiff') is not a number"},
      {"linear two lines", surfaces_plus(behavior + "LINEAR\n1e7\n2e7\n"), 36,
       "*SURFACE BEHAVIOR", "at most 1 data line"},
      {"tied without friction", surfaces_plus(behavior + "TIED\n1e7\n"), 34, "*SURFACE BEHAVIOR",
       "needs a *FRICTION"},
      {"default without elastic first material", first_material_without_elastic(), 37,
       "*SURFACE BEHAVIOR", "AIR has no *ELASTIC"},
      // *FRICTION, *CHANGE FRICTION
      {"friction coefficient", surfaces_plus(si + "*FRICTION\n0., 1e5\n"), 37, "*FRICTION",
       "friction coefficient must be positive"},
      {"friction fields", surfaces_plus(si + "*FRICTION\n0.2, 1, 2, 3\n"), 37, "*FRICTION",
       "at most 3 field(s)"},
      {"friction outside an interaction", surfaces_plus("*FRICTION\n0.2\n"), 33, "*FRICTION",
       "must follow a *SURFACE INTERACTION"},
      {"friction in a step without change",
       surfaces_plus(si + step + "*FRICTION\n0.2\n*END STEP\n"), 38, "*FRICTION",
       "must follow a *CHANGE FRICTION"},
      {"change of an unknown interaction",
       surfaces_plus(si + step + "*CHANGE FRICTION, INTERACTION=X\n*END STEP\n"), 38,
       "*CHANGE FRICTION", "surface interaction X is not defined"},
      {"change friction in the model", surfaces_plus("*CHANGE FRICTION, INTERACTION=SI\n"), 33,
       "*CHANGE FRICTION", "only allowed between *STEP and *END STEP"},
      // *CHANGE SURFACE BEHAVIOR
      {"behavior in a step without change",
       surfaces_plus(si + step + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e7\n*END STEP\n"),
       38, "*SURFACE BEHAVIOR", "must follow a *CHANGE SURFACE BEHAVIOR"},
      {"behavior after a friction change",
       surfaces_plus(si + step + "*CHANGE FRICTION, INTERACTION=SI\n*SURFACE BEHAVIOR, "
                     "PRESSURE-OVERCLOSURE=LINEAR\n1e7\n*END STEP\n"),
       39, "*SURFACE BEHAVIOR", "must follow a *CHANGE SURFACE BEHAVIOR"},
      {"friction after a behavior change",
       surfaces_plus(si + step + "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n*FRICTION\n0.2\n*END STEP\n"),
       39, "*FRICTION", "must follow a *CHANGE FRICTION"},
      {"changed to tied without friction",
       surfaces_plus(si + step + "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n*SURFACE BEHAVIOR, "
                     "PRESSURE-OVERCLOSURE=TIED\n1e7\n*END STEP\n"),
       39, "*SURFACE BEHAVIOR", "needs a *FRICTION card in interaction SI"},
      {"changed to tied without stiffness",
       surfaces_plus(si + "*FRICTION\n0.2\n" + step + "*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n"
                     "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n*END STEP\n"),
       41, "*SURFACE BEHAVIOR", "needs its stiffness K"},
      {"change of an unknown interaction's behavior",
       surfaces_plus(si + step + "*CHANGE SURFACE BEHAVIOR, INTERACTION=X\n*END STEP\n"), 38,
       "*CHANGE SURFACE BEHAVIOR", "surface interaction X is not defined"},
      {"change surface behavior in the model",
       surfaces_plus("*CHANGE SURFACE BEHAVIOR, INTERACTION=SI\n"), 33,
       "*CHANGE SURFACE BEHAVIOR", "only allowed between *STEP and *END STEP"},
      // *MODEL CHANGE (si: lines 33-35, the pair 36-37, the step 38-39)
      {"model change of elements",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=ELEMENT, REMOVE\n1\n*END STEP\n"),
       40, "*MODEL CHANGE", "TYPE=ELEMENT is not supported with contact or *TIE"},
      {"model change without type",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, REMOVE\nSLAVE, MASTER\n*END STEP\n"),
       40, "*MODEL CHANGE", "TYPE= is required"},
      {"model change of an unknown type",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=SURFACE, REMOVE\nSLAVE, MASTER\n*END STEP\n"),
       40, "*MODEL CHANGE", "TYPE=SURFACE: expected CONTACT PAIR"},
      {"model change adding and removing",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=CONTACT PAIR, ADD, REMOVE\nSLAVE, MASTER\n*END STEP\n"),
       40, "*MODEL CHANGE", "exactly one of ADD and REMOVE is required"},
      {"model change neither adding nor removing",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=CONTACT PAIR\nSLAVE, MASTER\n*END STEP\n"),
       40, "*MODEL CHANGE", "exactly one of ADD and REMOVE is required"},
      {"model change of a pair that is not there",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nMASTER, SLAVE\n*END STEP\n"),
       41, "*MODEL CHANGE", "no *CONTACT PAIR has slave surface MASTER and master surface SLAVE"},
      {"model change with one surface",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n" + step +
                     "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\nSLAVE\n*END STEP\n"),
       41, "*MODEL CHANGE", "expected at least 2 field(s)"},
      {"model change in the model",
       surfaces_plus(si + s2s + "\nSLAVE, MASTER\n*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE\n"
                     "SLAVE, MASTER\n"),
       38, "*MODEL CHANGE", "only allowed between *STEP and *END STEP"},
      // *CONTACT PRINT, *CONTACT FILE
      {"unknown contact print variable",
       surfaces_plus(step + "*CONTACT PRINT\nCDIS, CPRESS\n*END STEP\n"), 36, "*CONTACT PRINT",
       "unknown contact output variable CPRESS"},
      {"contact print totals", surfaces_plus(step + "*CONTACT PRINT, TOTALS=MAYBE\nCELS\n"), 35,
       "*CONTACT PRINT", "TOTALS=MAYBE"},
      {"contact print without variables", surfaces_plus(step + "*CONTACT PRINT\n*END STEP\n"),
       35, "*CONTACT PRINT", "no output variables given"},
      {"contact print time points",
       surfaces_plus(step + "*CONTACT PRINT, TIME POINTS=T\nCDIS\n"), 35, "*CONTACT PRINT",
       "time points T are not defined"},
      {"contact print before a step", surfaces_plus("*CONTACT PRINT\nCDIS\n"), 33,
       "*CONTACT PRINT", "only allowed between *STEP and *END STEP"},
      {"unknown contact file variable", surfaces_plus(step + "*CONTACT FILE\nU\n*END STEP\n"),
       36, "*CONTACT FILE", "unknown contact output variable U"},
      // *CONTROLS, PARAMETERS=CONTACT / LINE SEARCH
      {"contact alea", surfaces_plus(step + "*CONTROLS, PARAMETERS=CONTACT\n0.001, 1.5\n"), 36,
       "*CONTROLS", "alea (field 2) must lie in [0, 1]"},
      {"contact kscalemax",
       surfaces_plus(step + "*CONTROLS, PARAMETERS=CONTACT\n0.001, 0.1, 0.5\n"), 36, "*CONTROLS",
       "kscalemax (field 3) must be at least 1"},
      {"contact itf2f",
       surfaces_plus(step + "*CONTROLS, PARAMETERS=CONTACT\n0.001, 0.1, 100, 2.5\n"), 36,
       "*CONTROLS", "positive whole number"},
      {"contact delcon", surfaces_plus(step + "*CONTROLS, PARAMETERS=CONTACT\n-1\n"), 36,
       "*CONTROLS", "must not be negative"},
      {"line search bounds",
       surfaces_plus(step + "*CONTROLS, PARAMETERS=LINE SEARCH\n, 0.8, 0.5\n"), 36, "*CONTROLS",
       "upper bound (field 3) is below the lower bound"},
      {"line search lower bound",
       surfaces_plus(step + "*CONTROLS, PARAMETERS=LINE SEARCH\n, 0., 1.\n"), 36, "*CONTROLS",
       "lower bound (field 2) must be positive"},
  };
}

}  // namespace kontakt::inp::test
