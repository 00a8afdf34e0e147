"""Type stubs of zcheck: exact stability of time integrators, from Python."""

import os
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

Number = Union[int, float, Fraction, str, Any]  # Any: a SymPy number
Document = Dict[str, Any]

__version__: str

class Error(ValueError):
    """A method, number, parameter or file zcheck cannot take; the message
    is the command line's (file:line:column where there is one)."""

class Exact(str):
    """An exact number or polynomial as zcheck writes it."""

    def to_sympy(self) -> Any:
        """This value as a SymPy expression (needs SymPy)."""

def to_sympy(text: str) -> Any:
    """zcheck's exact text as a SymPy expression, exactly (needs SymPy)."""

class Method:
    """A time integrator, derived exactly once and kept."""

    @classmethod
    def from_zm(cls, text: str, name: str = "<string>") -> "Method":
        """A method from `.zm` source text."""
    @classmethod
    def from_file(cls, path: Union[str, "os.PathLike[str]"]) -> "Method":
        """A method from a `.zm` file or a `.toml` tableau or multistep file."""
    @classmethod
    def builtin(cls, name: str) -> "Method":
        """A built-in method by name."""
    @classmethod
    def from_tableau(
        cls,
        A: Sequence[Sequence[Number]],
        b: Sequence[Number],
        c: Optional[Sequence[Number]] = None,
        name: str = "tableau",
        bhat: Optional[Sequence[Number]] = None,
    ) -> "Method":
        """A Runge-Kutta method from its Butcher tableau, read exactly
        (``bhat``: an embedded estimator's weights)."""
    @classmethod
    def from_multistep(
        cls, alpha: Sequence[Number], beta: Sequence[Number], name: str = "multistep"
    ) -> "Method":
        """A linear multistep method from alpha and beta, lowest j first."""
    @classmethod
    def from_nodepy(cls, method: Any, name: Optional[str] = None) -> "Method":
        """A method from a NodePy Runge-Kutta or linear multistep object."""
    @property
    def name(self) -> str:
        """The method's name."""
    @property
    def params(self) -> List[str]:
        """The names of the method's parameters other than Phi."""
    @property
    def charpoly(self) -> Exact:
        """chi(z), exact."""
    @property
    def transition_matrix(self) -> List[List[Exact]]:
        """P, exact (for an implicit method, times its denominator)."""
    def derive(self) -> Document:
        """`zcheck derive --format json`."""
    def stability(self, **params: Number) -> Document:
        """`zcheck stability --format json`."""
    def region(self, **params: Number) -> Document:
        """`zcheck region --format json`."""
    def order(self, modified: Optional[int] = None, tolerance: Optional[Number] = None) -> Document:
        """`zcheck order --format json`: classical order, stage order,
        algebraic stability, symplecticity, SSP coefficient, ..."""
    def verify(self, phi: Number, steps: int = 100000, **params: Number) -> Document:
        """The numeric witnesses at phi (`check::verify`)."""

def map(
    method: Method,
    phi: Optional[Tuple[Number, Number]] = None,
    grid: int = 40,
    samples: int = 200,
    **params: Union[Number, Tuple[Number, Number]],
) -> Document:
    """`zcheck map --format json`, its grid as numpy arrays."""

def design(
    method: Method,
    maximize: str,
    min_order: Optional[int] = None,
    per: Optional[str] = None,
    **params: Union[Number, Tuple[Number, Number]],
) -> Document:
    """`zcheck design --format json`: free parameters (a tuple: a range)
    chosen for the best exact objective, with a certificate."""

def advise(
    scene: Union[str, "os.PathLike[str]"],
    solver: Optional[str] = ...,
    substeps: Optional[int] = ...,
    iterations: Optional[int] = ...,
    solvers: Optional[Sequence[str]] = ...,
) -> Document:
    """`zcheck advise --scene`, on TOML text or a path."""

def paper() -> List[Document]:
    """The claims of `zcheck paper --format json`."""
