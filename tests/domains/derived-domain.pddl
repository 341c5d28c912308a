; Derived predicates: unified-planning cannot read them; refused with the requirement named.
(define (domain der)
  (:requirements :typing :derived-predicates)
  (:types thing)
  (:predicates (done ?t - thing) (ok ?t - thing))
  (:derived (ok ?t - thing) (done ?t))
  (:action work :parameters (?t - thing) :precondition (not (done ?t)) :effect (done ?t)))
